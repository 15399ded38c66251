# SPDX-License-Identifier: GPL-3.0-or-later
"""lepp.plot with Debian's matplotlib (Agg: no display) and Mesh._repr_svg_ (the drawing
of `lepp render`, for notebooks)."""
import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.axes import Axes  # noqa: E402
from matplotlib.collections import LineCollection, PolyCollection  # noqa: E402

import lepp  # noqa: E402
from conftest import corpus  # noqa: E402


@pytest.fixture(scope="module")
def mesh():
    return lepp.refine(corpus("paper", "A.poly"), min_angle=20)


@pytest.fixture(autouse=True)
def close_figures():
    yield
    plt.close("all")


def outlined(ax):
    """The collections drawn with no fill and red edges: the bad triangles' outlines."""
    return [c for c in ax.collections if isinstance(c, PolyCollection) and len(c.get_facecolors()) == 0
            and tuple(c.get_edgecolors()[0]) == matplotlib.colors.to_rgba("red")]


def test_plot_returns_axes_with_a_colorbar(mesh, tmp_path):
    ax = lepp.plot(mesh)
    assert isinstance(ax, Axes)
    faces = ax.collections[0]
    assert faces.colorbar is not None and faces.colorbar.ax in ax.figure.axes
    assert faces.get_clim() == (0.0, 1.0) and "quality" in faces.colorbar.ax.get_ylabel()
    # One face per triangle, coloured by the .vtu's area quality.
    np.testing.assert_array_equal(faces.get_array(), mesh.to_meshio().cell_data["area_quality"][0])
    assert len(faces.get_paths()) == mesh.triangles.shape[0]
    # Constrained edges bold.
    lines = [c for c in ax.collections if isinstance(c, LineCollection) and not isinstance(c, PolyCollection)]
    assert len(lines) == 1 and len(lines[0].get_segments()) == mesh.edges.shape[0]
    ax.figure.savefig(tmp_path / "m.png")
    assert (tmp_path / "m.png").read_bytes().startswith(b"\x89PNG")


def test_plot_outlines_the_bad_triangles(mesh):
    angles = mesh.to_meshio().cell_data["min_angle"][0]
    # Refined for 20 degrees: nothing below 20 (the target by default), some below 30.
    assert outlined(lepp.plot(mesh)) == []
    ax = lepp.plot(mesh, min_angle=30, color="angle")
    (bad,) = outlined(ax)
    assert len(bad.get_paths()) == (angles < 30).sum() > 0
    np.testing.assert_array_equal(ax.collections[0].get_array(), angles)
    assert ax.collections[0].get_clim() == (0.0, 60.0)


def test_plot_on_given_axes_and_other_colours(mesh):
    fig, (left, right) = plt.subplots(1, 2)
    assert lepp.plot(mesh, ax=right, color="radius_ratio", colorbar=False) is right
    assert right.collections[0].colorbar is None and not left.collections
    values = np.arange(mesh.triangles.shape[0], dtype=float)
    np.testing.assert_array_equal(lepp.plot(mesh.to_dict(), color=values).collections[0].get_array(), values)
    with pytest.raises(ValueError, match="none of"):
        lepp.plot(mesh, color="blue")
    with pytest.raises(ValueError, match="values for"):
        lepp.plot(mesh, color=values[1:])


def test_repr_svg_is_the_render_drawing(mesh):
    svg = mesh._repr_svg_()
    assert svg.startswith("<svg ") and svg.rstrip().endswith("</svg>")
    assert svg == lepp.render(mesh, highlight_bad=True, min_angle=20, width=600)
    bad = lepp.refine(corpus("paper", "A.poly"), min_angle=20)
    bad.statistics = dict(bad.statistics, min_angle_target=30)  # bad triangles are marked in red
    assert 'stroke="red"' in bad._repr_svg_() and 'stroke="red"' not in svg


def test_repr_svg_of_a_huge_mesh_is_none(mesh, monkeypatch):
    monkeypatch.setattr(lepp.Mesh, "svg_max_triangles", mesh.triangles.shape[0] - 1)
    assert mesh._repr_svg_() is None
