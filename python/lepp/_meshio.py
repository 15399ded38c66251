# SPDX-License-Identifier: GPL-3.0-or-later
"""Mesh.to_meshio and lepp.from_meshio: a lepp mesh as a meshio.Mesh and back.

The triangles carry the cell data the .vtu writer writes (the measures of
lepp/stats.h, computed by the same C++ functions, and the region); the point
data is the .vtu's `input`. The constrained edges, which the .vtu does not
hold, are a block of 'line' cells with their boundary marker and input segment;
each cell data name has one array per block (meshio's rule), so the measures
are NaN on lines and marker, segment are 0, -1 on triangles.
"""
import numpy as np

from . import _lepp
from ._convert import mesh_dict


def _measures(arrays):
    return _lepp.triangle_measures(arrays)


def to_meshio(mesh, *, edges=True):
    import meshio

    arrays = mesh_dict(mesh)
    v, t = arrays["vertices"], arrays["triangles"]
    n, m = v.shape[0], t.shape[0]
    points = np.zeros((n, 3))
    points[:, :2] = v
    measures = _measures(arrays)
    regions = np.asarray(arrays.get("triangle_regions", ()), dtype=np.int32)
    if regions.size != m:  # no regions: 0, as the .vtu writes
        regions = np.zeros(m, dtype=np.int32)
    input_flags = np.zeros(n, dtype=np.uint8)
    input_flags[: int(arrays.get("input_vertices", 0) or 0)] = 1

    cells = [("triangle", t)]
    cell_data = {name: [values] for name, values in measures.items()}
    cell_data["region"] = [regions]
    lines = np.asarray(arrays.get("edges", np.zeros((0, 2))), dtype=np.int32).reshape(-1, 2)
    if edges and lines.shape[0]:
        k = lines.shape[0]
        markers = _per_edge(arrays.get("edge_markers"), k, 0)
        segments = _per_edge(arrays.get("edge_segments"), k, -1)
        cells.append(("line", lines))
        for name in measures:
            cell_data[name].append(np.full(k, np.nan))
        cell_data["region"].append(np.zeros(k, dtype=np.int32))
        cell_data["marker"] = [np.zeros(m, dtype=np.int32), markers]
        cell_data["segment"] = [np.full(m, -1, dtype=np.int32), segments]
    return meshio.Mesh(points, cells, point_data={"input": input_flags}, cell_data=cell_data)


def _per_edge(values, k, default):
    a = np.asarray(values if values is not None else (), dtype=np.int32)
    return a if a.size == k else np.full(k, default, dtype=np.int32)


def _cell_values(mesh, name, block):
    """The cell data `name` of cell block `block`, or None."""
    data = mesh.cell_data.get(name)
    if data is None or block >= len(data):
        return None
    return np.asarray(data[block])


def _gmsh_labels(mesh, block, prefix, none_name):
    """A .msh's physical groups as lepp writes them (docs/FORMATS.md): the tag of group
    `prefix`k is label k, the group `none_name` label 0. None when the names are not lepp's."""
    tags = _cell_values(mesh, "gmsh:physical", block)
    if tags is None or not mesh.field_data:
        return None
    label_of = {}
    for name, value in mesh.field_data.items():
        value = np.asarray(value).ravel()
        if value.size != 2:  # not a physical name's (tag, dimension)
            continue
        tag = value[0]
        if name == none_name:
            label_of[int(tag)] = 0
        elif name.startswith(prefix) and name[len(prefix):].isdigit():
            label_of[int(tag)] = int(name[len(prefix):])
    if not label_of or not all(int(x) in label_of for x in np.unique(tags)):
        return None
    return np.array([label_of[int(x)] for x in tags], dtype=np.int32)


def from_meshio(mesh):
    """A lepp.Mesh from a meshio.Mesh of triangles: Mesh.to_meshio's, meshio.read of a
    .vtu or .msh lepp wrote, or any 2D triangle mesh (points (n, 2), or (n, 3) with z = 0).
    Kept: the triangles (in order, as given), the 'line' cells as constrained edges with
    their marker and segment, the region of each triangle, and the input vertices (point
    data 'input': its leading ones). A .msh's physical groups named as lepp names them
    (region_k, domain, marker_m, unmarked) give the regions and markers. The mesh was
    not refined here: outcome and converged are None, statistics has the measures'
    vertices, triangles, min_angle, avg_min_angle and min_area_quality."""
    from ._mesh import Mesh

    points = np.asarray(mesh.points, dtype=np.float64)
    if points.ndim != 2 or points.shape[1] not in (2, 3):
        raise ValueError(f"from_meshio: points of shape {points.shape}: expected (n, 2) or (n, 3)")
    if points.shape[1] == 3 and np.any(points[:, 2] != 0):
        raise ValueError("from_meshio: points with z != 0: lepp meshes are planar (z = 0)")
    vertices = np.ascontiguousarray(points[:, :2])
    triangles, regions, lines, markers, segments = [], [], [], [], []
    for block, cells in enumerate(mesh.cells):
        data = np.asarray(cells.data)
        if cells.type == "triangle":
            triangles.append(data)
            r = _cell_values(mesh, "region", block)
            if r is None:
                r = _gmsh_labels(mesh, block, "region_", "domain")
            regions.append(r)
        elif cells.type == "line":
            lines.append(data)
            mk = _cell_values(mesh, "marker", block)
            if mk is None:
                mk = _gmsh_labels(mesh, block, "marker_", "unmarked")
            markers.append(mk)
            segments.append(_cell_values(mesh, "segment", block))
        elif cells.type != "vertex":  # a .msh's point elements say nothing about the triangles
            raise ValueError(f"from_meshio: cells of type '{cells.type}': lepp meshes have triangles "
                             "(and lines, the constrained edges)")
    if not triangles:
        raise ValueError("from_meshio: the mesh has no triangles")
    t = np.ascontiguousarray(np.concatenate(triangles), dtype=np.int32)
    if t.size and (t.min() < 0 or t.max() >= vertices.shape[0]):
        raise ValueError("from_meshio: a triangle names a point that does not exist")
    e = np.ascontiguousarray(np.concatenate(lines) if lines else np.zeros((0, 2)), dtype=np.int32)

    def joined(parts, lengths, default):
        if not parts or all(p is None for p in parts):
            return None
        return np.concatenate([np.full(n, default) if p is None else p for p, n in zip(parts, lengths)]).astype(np.int32)

    triangle_regions = joined(regions, [len(x) for x in triangles], 0)
    edge_markers = joined(markers, [len(x) for x in lines], 0)
    edge_segments = joined(segments, [len(x) for x in lines], -1)
    # lepp numbers the input vertices first: the leading ones of 'input'. Another pattern
    # is not lepp's layout, and none are known (0: certify finds them by coordinates).
    given = np.asarray(mesh.point_data.get("input", np.zeros(0))).reshape(-1) != 0
    leading = given.size if given.all() else int(np.argmin(given))
    input_vertices = leading if given.size == vertices.shape[0] and not given[leading:].any() else 0

    arrays = {"vertices": vertices, "triangles": t, "edges": e, "input_vertices": input_vertices}
    measures = _measures(arrays)
    result = {
        **arrays,
        "edge_segments": edge_segments if edge_segments is not None else np.full(e.shape[0], -1, dtype=np.int32),
        "edge_markers": edge_markers if edge_markers is not None else np.zeros(e.shape[0], dtype=np.int32),
        "triangle_regions": triangle_regions if triangle_regions is not None else np.zeros(0, dtype=np.int32),
        "region_count": int(triangle_regions.max(initial=0)) if triangle_regions is not None else 0,
        "trace": None,
        "unimprovable": [],
        "outcome": None,
        "converged": None,
        "statistics": {
            "vertices": vertices.shape[0],
            "triangles": t.shape[0],
            "min_angle": float(measures["min_angle"].min(initial=np.inf)) if t.size else 0.0,
            "avg_min_angle": float(measures["min_angle"].mean()) if t.size else 0.0,
            "min_area_quality": float(measures["area_quality"].min(initial=np.inf)) if t.size else 0.0,
        },
        "warnings": [],
    }
    return Mesh(result)
