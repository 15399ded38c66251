# SPDX-License-Identifier: GPL-3.0-or-later
"""lepp.triangulate on the examples of the `triangle` package's documentation (a square
with a quality and area bound, a ring with a hole, a spiral point set, an open boundary
closed by its convex hull), written from their description; switches and markers."""
import math

import numpy as np
import pytest

import lepp


def areas(t):
    v, tri = t["vertices"], t["triangles"]
    a, b, c = v[tri[:, 0]], v[tri[:, 1]], v[tri[:, 2]]
    return 0.5 * ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))


def min_angles(t):
    v, tri = t["vertices"], t["triangles"]
    out = []
    for abc in v[tri]:
        angles = []
        for i in range(3):
            p, q, r = abc[i], abc[(i + 1) % 3], abc[(i + 2) % 3]
            u, w = q - p, r - p
            angles.append(math.degrees(math.atan2(abs(u[0] * w[1] - u[1] * w[0]), u @ w)))
        out.append(min(angles))
    return np.array(out)


def circle(n, r):
    i = np.arange(n)
    theta = i * 2 * np.pi / n
    pts = np.stack([np.cos(theta), np.sin(theta)], axis=1) * r
    seg = np.stack([i, i + 1], axis=1) % n
    return pts, seg


def test_square_with_quality_and_area_bound():
    """The documentation's first example: the unit square's four corners, switches 'qa0.1'."""
    t = lepp.triangulate({"vertices": np.array([[0, 0], [0, 1], [1, 1], [1, 0]])}, "qa0.1")
    assert set(t) == {"vertices", "vertex_markers", "triangles"}
    assert t["vertices"].shape[1] == 2 and t["triangles"].shape[1] == 3
    assert t["vertex_markers"].shape == (t["vertices"].shape[0], 1)
    assert (areas(t) > 0).all() and (areas(t) <= 0.1).all()
    assert math.isclose(areas(t).sum(), 1.0)
    assert min_angles(t).min() >= 20 - 1e-9
    on_boundary = (np.isclose(t["vertices"], 0) | np.isclose(t["vertices"], 1)).any(axis=1)
    np.testing.assert_array_equal(t["vertex_markers"][:, 0], on_boundary.astype(int))


def test_ring_with_a_hole():
    """Two concentric circles as segments, a hole point at the centre, switches 'qpa0.05'."""
    outer, so = circle(32, 1.0)
    inner, si = circle(16, 0.5)
    tri = {"vertices": np.vstack([outer, inner]), "segments": np.vstack([so, si + 32]), "holes": [[0, 0]]}
    t = lepp.triangulate(tri, "qpa0.05")
    assert {"segments", "segment_markers", "holes"} <= set(t)
    centroids = t["vertices"][t["triangles"]].mean(axis=1)
    assert (np.hypot(centroids[:, 0], centroids[:, 1]) > 0.5 - 1e-9).all()  # nothing in the hole
    assert (areas(t) <= 0.05).all() and min_angles(t).min() >= 20 - 1e-9
    assert lepp.certify(tri, t, min_angle=20, max_area=0.05).ok
    # Boundary segments get marker 1 (they have none), the vertices on them too.
    assert (t["segment_markers"] == 1).all()
    assert t["vertex_markers"][np.unique(t["segments"])].min() == 1


def test_spiral_point_set():
    """Points on a spiral, no segments, switch 'q': the convex hull meshed with quality."""
    k = np.arange(1, 31)
    r, a = k / 10, k * 0.6
    pts = np.stack([r * np.cos(a), r * np.sin(a)], axis=1)
    t = lepp.triangulate({"vertices": pts}, "q")
    assert min_angles(t).min() >= 20 - 1e-9
    plain = lepp.triangulate({"vertices": pts})  # no switch: the Delaunay triangulation of the points
    assert plain["vertices"].shape[0] == 30
    np.testing.assert_array_equal(t["vertices"][:30], pts)


def test_convex_hull_closes_an_open_boundary():
    """A zigzag of segments that encloses nothing, switches 'pc': the hull's edges close it."""
    v = np.array([[0, 0], [2, 1], [4, 0], [6, 1], [3, 5]], dtype=float)
    s = np.array([[0, 1], [1, 2], [2, 3]])
    t = lepp.triangulate({"vertices": v, "segments": s}, "pcq25")
    hull = v[[0, 2, 3, 4]]  # (2, 1) is inside
    hull_area = 0.5 * sum(hull[i, 0] * hull[(i + 1) % 4, 1] - hull[(i + 1) % 4, 0] * hull[i, 1] for i in range(4))
    assert math.isclose(areas(t).sum(), hull_area, rel_tol=1e-12)
    assert min_angles(t).min() >= 25 - 1e-9
    with pytest.raises(lepp.InputError):  # without c the open zigzag bounds no region
        lepp.triangulate({"vertices": v, "segments": s}, "pq25")


def test_without_p_segments_and_holes_are_ignored():
    outer, so = circle(12, 1.0)
    t = lepp.triangulate({"vertices": outer, "segments": so, "holes": [[0, 0]]}, "")
    assert "segments" not in t and t["triangles"].shape[0] == 10  # a fan of the 12-gon, hole ignored


def test_area_bounds_built_from_floats():
    """str(1e-06) is '1e-06': the exponent is read (the triangle package's issue with small bounds)."""
    side = 0.01
    sq = {"vertices": np.array([[0, 0], [side, 0], [side, side], [0, side]])}
    bound = 1e-6
    t = lepp.triangulate(sq, "pq30a" + str(bound))
    assert (areas(t) <= bound).all() and areas(t).size >= side * side / bound


def test_regions_with_area_bounds():
    """'a' without a number: each region's own bound (a region row is x, y, attribute, max_area)."""
    v = np.array([[0, 0], [2, 0], [2, 1], [0, 1], [1, 0], [1, 1]], dtype=float)
    s = np.array([[0, 4], [4, 1], [1, 2], [2, 5], [5, 3], [3, 0], [4, 5]])
    tri = {"vertices": v, "segments": s, "regions": [[0.5, 0.5, 1, 0.01], [1.5, 0.5, 2, 0.1]]}
    t = lepp.triangulate(tri, "pqa")
    c = t["vertices"][t["triangles"]].mean(axis=1)
    assert (areas(t)[c[:, 0] < 1] <= 0.01).all() and (areas(t)[c[:, 0] > 1] <= 0.1).all()
    assert (areas(t)[c[:, 0] > 1] > 0.01).any()


def test_duplicate_vertices_and_repeated_calls_do_not_crash():
    v = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [1, 1], [0.5, 0.5], [0.5, 0.5]])
    for _ in range(20):
        t = lepp.triangulate({"vertices": v}, "q30")
        assert t["vertices"].shape[0] >= 5
    assert (areas(t) > 0).all()


def test_markers_are_kept():
    v = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
    s = np.array([[0, 1], [1, 2], [2, 3], [3, 0]])
    t = lepp.triangulate({"vertices": v, "vertex_markers": [[7], [0], [0], [0]], "segments": s,
                          "segment_markers": [5, 0, 0, 0]}, "pqa0.05")
    assert t["vertex_markers"][0, 0] == 7
    on_bottom = np.isclose(t["vertices"][:, 1], 0) & (t["vertices"][:, 0] > 0) & (t["vertices"][:, 0] < 1)
    assert on_bottom.any() and (t["vertex_markers"][on_bottom, 0] == 5).all()
    bottom_edges = np.isclose(t["vertices"][t["segments"]][:, :, 1], 0).all(axis=1)
    assert (t["segment_markers"][bottom_edges, 0] == 5).all() and (t["segment_markers"][~bottom_edges, 0] == 1).all()


@pytest.mark.parametrize("interior_marker", [0, 9])
def test_interior_segment_markers(interior_marker):
    """Triangle's rule for a segment inside the domain: it keeps its marker, 0 included (only a
    boundary segment without one gets 1), and so do the vertices added on it."""
    v = np.array([[0, 0], [4, 0], [4, 4], [0, 4], [1, 2], [3, 2]], dtype=float)
    s = np.array([[0, 1], [1, 2], [2, 3], [3, 0], [4, 5]])  # a square, and a segment inside it
    t = lepp.triangulate({"vertices": v, "segments": s, "segment_markers": [0, 0, 0, 0, interior_marker]},
                         "pq30a0.05")
    ends = t["vertices"][t["segments"]]
    inside = np.isclose(ends[:, :, 1], 2).all(axis=1) & (ends[:, :, 0] > 0.5).all(axis=1) & (ends[:, :, 0] < 3.5).all(axis=1)
    assert inside.sum() > 1 and (~inside).sum() > 4  # both kinds of segment were split
    np.testing.assert_array_equal(t["segment_markers"][inside, 0], interior_marker)
    np.testing.assert_array_equal(t["segment_markers"][~inside, 0], 1)
    x, y = t["vertices"][:, 0], t["vertices"][:, 1]
    on_boundary = np.isclose(x, 0) | np.isclose(x, 4) | np.isclose(y, 0) | np.isclose(y, 4)
    on_interior = np.isclose(y, 2) & (x > 1 - 1e-9) & (x < 3 + 1e-9)
    assert on_interior.sum() > 2
    np.testing.assert_array_equal(t["vertex_markers"][on_boundary, 0], 1)
    np.testing.assert_array_equal(t["vertex_markers"][on_interior, 0], interior_marker)
    np.testing.assert_array_equal(t["vertex_markers"][~on_boundary & ~on_interior, 0], 0)


@pytest.mark.parametrize("opts,switch", [("pqD", "D"), ("pr", "r"), ("pA", "A"), ("pq30e", "e"), ("pqV", "V"),
                                         ("pqo2", "o"), ("pqY", "Y"), ("pS10", "S")])
def test_unsupported_switches_are_named(opts, switch):
    sq = {"vertices": np.array([[0, 0], [1, 0], [1, 1], [0, 1]])}
    with pytest.raises(ValueError, match=f"switch '{switch}'"):
        lepp.triangulate(sq, opts)
    with pytest.raises(ValueError, match="no switch"):
        lepp.triangulate(sq, "pq#")


def test_bad_input_is_input_error():
    with pytest.raises(lepp.InputError):
        lepp.triangulate({"vertices": [[0, 0], [1, 1]]}, "p")
    with pytest.raises(lepp.InputError):
        lepp.triangulate({"segments": [[0, 1]]}, "p")
    with pytest.raises(ValueError, match="'triangles'"):
        lepp.triangulate({"vertices": [[0, 0], [1, 0], [0, 1]], "triangles": [[0, 1, 2]]}, "r")
