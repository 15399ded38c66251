# SPDX-License-Identifier: GPL-3.0-or-later
"""Mesh.write with the format taken from the file name, read back by meshio (Debian's
python3-meshio); Mesh.to_meshio and lepp.from_meshio, in memory and through files."""
import os

import meshio
import numpy as np
import pytest

import lepp
from conftest import SOURCE, corpus

# Markers 1 to 6 on the boundary and the cut, two regions, a hole, a region point on a segment.
LABELLED = os.path.join(SOURCE, "tests", "formats", "data", "labelled.poly")


@pytest.fixture(scope="module")
def mesh():
    m = lepp.refine(LABELLED, min_angle=28, max_area=0.02)
    assert m.converged and (m.triangle_regions > 0).all() and set(m.edge_markers) == {1, 2, 3, 4, 5, 6}
    return m


def files(directory):
    return sorted(p.name for p in directory.iterdir())


@pytest.mark.parametrize("name,kwargs,format,written", [
    ("m.vtu", {}, "vtu", ["m.vtu"]),
    ("m.msh", {}, "msh4", ["m.msh"]),
    ("m.msh", {"msh_version": 4.1}, "msh4", ["m.msh"]),
    ("m.msh", {"msh_version": 2.2}, "msh2", ["m.msh"]),
    ("m.msh", {"msh_version": "2.2", "binary": True}, "msh2", ["m.msh"]),
    ("m.node", {}, "triangle", ["m.ele", "m.node", "m.poly"]),
    ("m.ele", {}, "triangle", ["m.ele", "m.node", "m.poly"]),
    ("m.poly", {}, "triangle", ["m.ele", "m.node", "m.poly"]),
    ("m", {}, "triangle", ["m.ele", "m.node", "m.poly"]),
    ("run.1", {}, "triangle", ["run.1.ele", "run.1.node", "run.1.poly"]),  # an unknown suffix is the prefix's
])
def test_write_takes_the_format_from_the_extension(mesh, tmp_path, name, kwargs, format, written):
    """The bytes of write(prefix, format=...) (the command's, test_refine.py), under the file's name."""
    (tmp_path / "by-name").mkdir()
    (tmp_path / "by-format").mkdir()
    mesh.write(tmp_path / "by-name" / name, **kwargs)
    prefix = os.path.splitext(written[0])[0]
    mesh.write(str(tmp_path / "by-format" / prefix), format=format, binary=kwargs.get("binary", False))
    assert files(tmp_path / "by-name") == written
    for f in written:
        assert (tmp_path / "by-name" / f).read_bytes() == (tmp_path / "by-format" / f).read_bytes(), f
    if format.startswith("msh"):
        header = (tmp_path / "by-name" / written[0]).read_bytes()[:20]
        assert header.startswith(b"$MeshFormat\n" + (b"2.2 " if format == "msh2" else b"4.1 "))


def test_a_prefix_with_format_is_as_before(mesh, tmp_path):
    mesh.write(tmp_path / "p.vtu", format="vtu")  # a prefix stays a prefix when the format is given
    mesh.write(tmp_path / "q", "triangle,vtu")
    assert files(tmp_path) == ["p.vtu.vtu", "q.ele", "q.node", "q.poly", "q.vtu"]


def test_msh_version_errors(mesh, tmp_path):
    with pytest.raises(ValueError, match="2.2 or 4.1"):
        mesh.write(tmp_path / "m.msh", msh_version=3)
    with pytest.raises(ValueError, match="only for a .msh path"):
        mesh.write(tmp_path / "m.vtu", msh_version=2.2)
    with pytest.raises(ValueError, match="with format"):
        mesh.write(tmp_path / "m", format="msh4", msh_version=2.2)
    assert files(tmp_path) == []


def test_vtu_read_back_by_meshio(mesh, tmp_path):
    mesh.write(tmp_path / "m.vtu")
    back = meshio.read(tmp_path / "m.vtu")
    np.testing.assert_array_equal(back.points[:, :2], mesh.vertices)
    assert (back.points[:, 2] == 0).all()
    assert [c.type for c in back.cells] == ["triangle"]
    np.testing.assert_array_equal(back.cells[0].data, mesh.triangles)
    np.testing.assert_array_equal(back.cell_data["region"][0], mesh.triangle_regions)
    np.testing.assert_array_equal(back.point_data["input"], mesh.vertex_markers)
    # The .vtu's arrays are to_meshio's, value for value.
    ours = mesh.to_meshio()
    assert set(back.cell_data) == set(ours.cell_data) - {"marker", "segment"}
    for name in back.cell_data:
        np.testing.assert_array_equal(back.cell_data[name][0], ours.cell_data[name][0], err_msg=name)
    assert ours.cell_data["min_angle"][0].min() == mesh.statistics["min_angle"]


@pytest.mark.parametrize("version", [2.2, 4.1])
def test_msh_read_back_by_meshio(mesh, tmp_path, version):
    mesh.write(tmp_path / "m.msh", msh_version=version)
    back = meshio.read(tmp_path / "m.msh")
    np.testing.assert_array_equal(back.points[:, :2], mesh.vertices)
    # Gmsh 4.1 files hold one element block per group: compare the triangles and lines as sets.
    tris = {tuple(t) for t in np.concatenate([c.data for c in back.cells if c.type == "triangle"])}
    lines = {tuple(e) for e in np.concatenate([c.data for c in back.cells if c.type == "line"])}
    assert tris == {tuple(t) for t in mesh.triangles} and len(tris) == mesh.triangles.shape[0]
    assert lines == {tuple(e) for e in mesh.edges}
    # The physical groups, named as lepp names them, give back the regions and markers.
    again = lepp.from_meshio(back)
    region = dict(zip(map(tuple, mesh.triangles), mesh.triangle_regions))
    assert {tuple(t): r for t, r in zip(again.triangles, again.triangle_regions)} == region
    marker = dict(zip(map(tuple, mesh.edges), mesh.edge_markers))
    assert {tuple(e): k for e, k in zip(again.edges, again.edge_markers)} == marker


def assert_same_mesh(a, b):
    for name in ("vertices", "triangles", "edges", "edge_markers", "edge_segments", "triangle_regions",
                 "vertex_markers"):
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name), err_msg=name)
    assert a.input_vertices == b.input_vertices


def test_to_meshio_from_meshio_round_trip(mesh, tmp_path):
    m = mesh.to_meshio()
    assert [c.type for c in m.cells] == ["triangle", "line"]
    np.testing.assert_array_equal(m.cells[1].data, mesh.edges)
    np.testing.assert_array_equal(m.cell_data["marker"][1], mesh.edge_markers)
    np.testing.assert_array_equal(m.cell_data["segment"][1], mesh.edge_segments)
    back = lepp.from_meshio(m)
    assert_same_mesh(back, mesh)
    assert back.outcome is None and back.converged is None and "not refined here" in repr(back)
    assert back.statistics["min_angle"] == mesh.statistics["min_angle"]
    # The mesh read back writes the same files.
    mesh.write(tmp_path / "a.vtu")
    back.write(tmp_path / "b.vtu")
    mesh.write(tmp_path / "a")
    back.write(tmp_path / "b")
    for ext in (".vtu", ".node", ".ele", ".poly"):
        assert (tmp_path / ("a" + ext)).read_bytes() == (tmp_path / ("b" + ext)).read_bytes(), ext
    # And through meshio's own writer and reader (the lines and their data survive a .vtu).
    meshio.write(tmp_path / "c.vtu", m)
    assert_same_mesh(lepp.from_meshio(meshio.read(tmp_path / "c.vtu")), mesh)


def test_to_meshio_without_edges_and_without_labels(tmp_path):
    mesh = lepp.refine(corpus("paper", "A.poly"), min_angle=25)
    m = mesh.to_meshio(edges=False)
    assert [c.type for c in m.cells] == ["triangle"] and (m.cell_data["region"][0] == 0).all()
    back = lepp.from_meshio(m)
    assert back.edges.shape == (0, 2) and back.input_vertices == mesh.input_vertices
    np.testing.assert_array_equal(back.triangles, mesh.triangles)


def test_from_meshio_of_any_triangle_mesh():
    """Another program's mesh: 2D points, no cell or point data; nothing is made up."""
    points = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    m = lepp.from_meshio(meshio.Mesh(points, [("triangle", [[0, 1, 2], [0, 2, 3]]), ("vertex", [[0]])]))
    np.testing.assert_array_equal(m.vertices, points)
    assert m.triangles.dtype == np.int32 and m.triangles.shape == (2, 3)
    assert m.input_vertices == 0 and m.triangle_regions.size == 0 and m.edges.shape == (0, 2)
    assert m.statistics["min_angle"] == pytest.approx(45) and m.statistics["triangles"] == 2
    assert lepp.certify((points, [[0, 1], [1, 2], [2, 3], [3, 0]]), m).ok
    # Input flags that are not lepp's layout (input vertices first) mean none are known.
    odd = meshio.Mesh(points, [("triangle", [[0, 1, 2], [0, 2, 3]])], point_data={"input": [0, 1, 1, 0]})
    assert lepp.from_meshio(odd).input_vertices == 0
    firsts = meshio.Mesh(points, [("triangle", [[0, 1, 2], [0, 2, 3]])], point_data={"input": [1, 1, 0, 0]})
    assert lepp.from_meshio(firsts).input_vertices == 2
    # Physical groups that lepp did not name are not read as regions or markers.
    gmsh = meshio.Mesh(points, [("triangle", [[0, 1, 2], [0, 2, 3]]), ("line", [[0, 1]])],
                       cell_data={"gmsh:physical": [[7, 7], [3]]}, field_data={"fluid": [7, 2], "inlet": [3, 1]})
    g = lepp.from_meshio(gmsh)
    assert g.triangle_regions.size == 0 and g.edge_markers.tolist() == [0] and g.edges.tolist() == [[0, 1]]
    named = meshio.Mesh(points, gmsh.cells, cell_data=gmsh.cell_data, field_data={"region_2": [7, 2], "marker_5": [3, 1]})
    n = lepp.from_meshio(named)
    assert n.triangle_regions.tolist() == [2, 2] and n.edge_markers.tolist() == [5]


@pytest.mark.parametrize("bad,match", [
    (meshio.Mesh(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 1.0]]), [("triangle", [[0, 1, 2]])]), "z != 0"),
    (meshio.Mesh(np.array([[0, 0], [1, 0], [1, 1], [0, 1.0]]), [("quad", [[0, 1, 2, 3]])]), "'quad'"),
    (meshio.Mesh(np.array([[0, 0], [1, 0.0]]), [("line", [[0, 1]])]), "no triangles"),
    (meshio.Mesh(np.array([[0, 0], [1, 0], [0, 1.0]]), [("triangle", [[0, 1, 3]])]), "does not exist"),
])
def test_from_meshio_refuses_what_is_no_lepp_mesh(bad, match):
    with pytest.raises(ValueError, match=match):
        lepp.from_meshio(bad)
