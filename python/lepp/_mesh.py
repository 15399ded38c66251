# SPDX-License-Identifier: GPL-3.0-or-later
"""lepp.Mesh: what lepp.refine returns."""
import os

import numpy as np

from . import _lepp


class Mesh:
    """A refined mesh.

    vertices        (n, 2) float64: the input vertices first, in input order (after
                    validation merged duplicates), then the Steiner points in
                    insertion order
    triangles       (m, 3) int32, counter-clockwise, 0-based
    vertex_markers  (n,) int32: 1 input vertex, 0 Steiner point (as PREFIX.node)
    edges           (k, 2) int32: the constrained edges (pieces of input segments)
    edge_segments   (k,) int32: the input segment each lies on (0-based, -1 unknown)
    edge_markers    (k,) int32: that segment's marker
    triangle_regions (m,) int32: k + 1 for the input's region k (regions[k]), 0 for none;
                    empty when the input has no regions
    input_vertices  how many leading vertices are input vertices
    trace           (s, 2) float64 Steiner points in insertion order (trace=True), else None
    trace_rules     the paper's rule that chose each point (trace=True), else None
    unimprovable    triangles left bad by the small-input-angle rule (list of dicts)
    outcome         'converged', 'unimprovable', 'steiner-budget', 'edge-floor' or 'time-limit'
                    (None for a mesh from lepp.from_meshio)
    converged       outcome is 'converged' (lepp refine's exit status 0; None from from_meshio)
    statistics      dict: the keys of `lepp refine --json` (from_meshio: the measures' few)
    warnings        what validation repaired (lepp refine's warnings)
    """

    def __init__(self, result):
        self.vertices = result["vertices"]
        self.triangles = result["triangles"]
        self.input_vertices = int(result["input_vertices"])
        markers = np.zeros(self.vertices.shape[0], dtype=np.int32)
        markers[: self.input_vertices] = 1
        self.vertex_markers = markers
        self.edges = result["edges"]
        self.edge_segments = result["edge_segments"]
        self.edge_markers = result["edge_markers"]
        self.triangle_regions = result["triangle_regions"]
        self._region_count = int(result["region_count"])
        self.trace = result["trace"]
        self.trace_rules = result.get("trace_rules")
        self.unimprovable = result["unimprovable"]
        self.outcome = result["outcome"]
        self.converged = None if result["converged"] is None else bool(result["converged"])
        self.statistics = result["statistics"]
        self.warnings = list(result["warnings"])
        self._input_vertex_markers = result.get("input_vertex_markers")

    def __repr__(self):
        return (f"<lepp.Mesh {self.vertices.shape[0]} vertices, {self.triangles.shape[0]} triangles, "
                f"smallest angle {self.statistics['min_angle']:.4f} deg, {self.outcome or 'not refined here'}>")

    def _arrays(self):
        return {
            "vertices": self.vertices,
            "triangles": self.triangles,
            "edges": self.edges,
            "edge_segments": self.edge_segments,
            "input_vertices": self.input_vertices,
            "edge_markers": self.edge_markers,
            "triangle_regions": self.triangle_regions,
            "region_count": self._region_count,
        }

    def to_dict(self):
        """The mesh as a plain dict (vertices, triangles, edges, edge_segments, input_vertices, trace):
        what a lepp.audit engine may return, and what lepp.certify and lepp.render take."""
        d = self._arrays()
        d["trace"] = self.trace
        return d

    def write(self, path, format=None, *, binary=False, msh_version=None):
        """Writes the mesh (docs/FORMATS.md). With no format, the file name says which:
        'm.vtu' VTK XML (ParaView, meshio: each triangle's quality and region); 'm.msh' Gmsh
        (msh_version 4.1, the default, or 2.2; binary=True for Gmsh's binary variant); 'm.node',
        'm.ele', 'm.poly' or a name with no extension ('m'): Triangle's m.node, m.ele, m.poly.
        Any other suffix is part of the prefix, as it always was ('run.1' writes run.1.node...).
        With format, path is a prefix, as `lepp refine -o PREFIX --format FORMAT` takes it:
        'triangle' PREFIX.node, PREFIX.ele, PREFIX.poly; 'vtu' PREFIX.vtu; 'msh2' or 'msh4'
        PREFIX.msh (Gmsh 2.2 or 4.1). format may list several ('triangle,vtu' or a list).
        PREFIX.unimprovable too when triangles were left bad by the small-input-angle rule."""
        path = os.fspath(path)
        if format is None:
            prefix, formats = _formats_of_path(path, msh_version)
        else:
            if msh_version is not None:
                raise ValueError("msh_version: only with a .msh path and no format "
                                 "(with format, say format='msh2' or 'msh4')")
            prefix = path
            formats = format.split(",") if isinstance(format, str) else list(format)
        _lepp.write_mesh(prefix, self._arrays(), [f.strip() for f in formats], bool(binary), self.unimprovable)

    def to_meshio(self, *, edges=True):
        """The mesh as a meshio.Mesh (needs meshio): what meshio.read gives for the .vtu
        this mesh writes (points (n, 3) with z = 0, the triangles, cell data min_angle,
        max_angle, area_quality, radius_ratio, edge_ratio, region; point data input), and
        with edges=True a block of 'line' cells, the constrained edges, with cell data
        marker (the boundary marker) and segment (the input segment). lepp.from_meshio
        reads it back."""
        from ._meshio import to_meshio
        return to_meshio(self, edges=edges)

    # Jupyter draws a mesh by this; above the cap it returns None (the text repr is shown)
    # rather than an SVG too large for a notebook.
    svg_max_triangles = 100_000

    def _repr_svg_(self):
        """The drawing of `lepp render` (coloured by quality, triangles below the target
        angle marked), for notebooks; None above svg_max_triangles triangles."""
        if self.triangles.shape[0] == 0 or self.triangles.shape[0] > self.svg_max_triangles:
            return None
        return _lepp.render_svg(self._arrays(), "quality", True, float(self._target_angle()), 600.0, "", [], [])

    def _target_angle(self):
        """The angle the mesh was refined for (30, render's default, when unknown)."""
        target = self.statistics.get("min_angle_target") if self.statistics else None
        return 30.0 if target is None else float(target)


# The file names Mesh.write knows by their extension.
_TRIANGLE_EXTENSIONS = (".node", ".ele", ".poly")
_MSH_VERSIONS = {"2.2": "msh2", "4.1": "msh4"}


def _formats_of_path(path, msh_version):
    """(prefix, [format]) for Mesh.write(path) with no format."""
    root, ext = os.path.splitext(path)
    if ext == ".msh":
        version = "4.1" if msh_version is None else str(msh_version)
        if version not in _MSH_VERSIONS:
            raise ValueError(f"msh_version: 2.2 or 4.1, not {msh_version!r}")
        return root, [_MSH_VERSIONS[version]]
    if msh_version is not None:
        raise ValueError(f"msh_version: only for a .msh path, not {path!r}")
    if ext == ".vtu":
        return root, ["vtu"]
    if ext in _TRIANGLE_EXTENSIONS:
        return root, ["triangle"]
    return path, ["triangle"]  # no extension, or one that is part of the prefix (as before)
