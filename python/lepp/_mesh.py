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
    converged       outcome is 'converged' (lepp refine's exit status 0)
    statistics      dict: the keys of `lepp refine --json`
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
        self.converged = bool(result["converged"])
        self.statistics = result["statistics"]
        self.warnings = list(result["warnings"])
        self._input_vertex_markers = result.get("input_vertex_markers")

    def __repr__(self):
        return (f"<lepp.Mesh {self.vertices.shape[0]} vertices, {self.triangles.shape[0]} triangles, "
                f"smallest angle {self.statistics['min_angle']:.4f} deg, {self.outcome}>")

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

    def write(self, prefix, format="triangle", *, binary=False):
        """Writes the mesh as `lepp refine -o PREFIX --format FORMAT` does (docs/FORMATS.md):
        'triangle' PREFIX.node, PREFIX.ele, PREFIX.poly; 'vtu' PREFIX.vtu (VTK XML, with the
        quality of each triangle and its region); 'msh2' or 'msh4' PREFIX.msh (Gmsh 2.2 or
        4.1, physical groups from the boundary markers and regions; binary=True for Gmsh's
        binary variant). format may list several ('triangle,vtu' or a list). PREFIX.unimprovable
        too when triangles were left bad by the small-input-angle rule."""
        formats = format.split(",") if isinstance(format, str) else list(format)
        _lepp.write_mesh(os.fspath(prefix), self._arrays(), [f.strip() for f in formats], bool(binary),
                         self.unimprovable)
