# SPDX-License-Identifier: GPL-3.0-or-later
"""lepp.triangulate: the `triangle` package's call (a dict in, a dict out, Triangle's
switches), so code written for it runs on lepp. Only the switches that make sense for
lepp's meshes are taken; any other raises a ValueError that names it."""
import re

import numpy as np

from ._convert import InputError, pslg_dict

# Each switch lepp takes, and what it does.
SUPPORTED = {
    "p": "triangulate the PSLG: segments, holes and regions (without p: the vertices' convex hull)",
    "q": "quality: no angle below the number that follows, degrees (20 without one)",
    "a": "area bound: the number that follows for every triangle; without one, each region's bound",
    "c": "also mesh the convex hull (its edges become segments)",
    "Q": "quiet (lepp prints nothing anyway)",
    "z": "number from zero (the triangle package always does)",
}
# Triangle's switches lepp does not take, with what they do, for the error message.
UNSUPPORTED = {
    "r": "refine a previous mesh", "u": "a user-defined triangle constraint", "A": "regional attributes",
    "D": "conforming Delaunay", "j": "jettison unused vertices", "e": "edge list", "v": "Voronoi diagram",
    "n": "neighbour list", "g": "OFF file", "B": "no boundary markers", "P": "no .poly output",
    "N": "no .node output", "E": "no .ele output", "I": "no iteration numbers", "O": "no holes",
    "X": "no exact arithmetic", "o": "second-order (6-node) triangles", "Y": "no Steiner points on the boundary",
    "S": "a Steiner point budget (use lepp.refine(max_steiner=...))", "i": "incremental algorithm",
    "F": "Fortune's sweepline", "l": "vertical cuts only", "s": "segment splitting", "C": "consistency check",
    "V": "verbose", "h": "help",
}
# A number as Triangle reads it, and an exponent besides (so str(1e-05) works).
_NUMBER = re.compile(r"(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")


def parse_switches(opts):
    """{'p': bool, 'q': angle or None, 'a': area, 'a_regions': bool, 'c': bool} from a switch string."""
    out = {"p": False, "q": None, "a": None, "a_regions": False, "c": False}
    i = 0
    while i < len(opts):
        s = opts[i]
        i += 1
        if s in " -":
            continue
        number = None
        m = _NUMBER.match(opts, i)
        if s in "qa" and m:
            number = float(m.group(0))
            i = m.end()
        if s == "p":
            out["p"] = True
        elif s == "q":
            out["q"] = 20.0 if number is None else number
        elif s == "a":
            if number is None:
                out["a_regions"] = True
            else:
                out["a"] = number
        elif s == "c":
            out["c"] = True
        elif s in "Qz":
            pass
        elif s in UNSUPPORTED:
            raise ValueError(f"lepp.triangulate: switch '{s}' ({UNSUPPORTED[s]}) is not supported by lepp; "
                             f"it takes {' '.join(SUPPORTED)} (and the numbers after q and a)")
        else:
            raise ValueError(f"lepp.triangulate: '{s}' in {opts!r} is no switch of Triangle's; "
                             f"lepp takes {' '.join(SUPPORTED)}")
    return out


def _boundary_edges(triangles):
    """The set of edges (a, b), a < b, that lie on one triangle only."""
    t = np.asarray(triangles)
    e = np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    e.sort(axis=1)
    unique, counts = np.unique(e, axis=0, return_counts=True)
    return {tuple(x) for x in unique[counts == 1]}


def triangulate(tri, opts=""):
    """Triangulates the `triangle` package's dict with Triangle's switches (p q a c Q z),
    by lepp's Lepp-centroid refinement, and returns the same kind of dict: vertices (n, 2),
    vertex_markers (n, 1), triangles (m, 3), with p also segments (k, 2) and
    segment_markers (k, 1) (the constrained edges), holes and regions as given. Indices are
    0-based. Markers are Triangle's: an input vertex keeps a nonzero marker, a vertex on a
    segment gets that segment's marker, a boundary vertex or segment with none gets 1.
    Bad input raises lepp.InputError; an unsupported switch or key raises ValueError.
    """
    from . import refine  # the package's refine: this module is imported by it

    if not isinstance(tri, dict) or "vertices" not in tri:
        raise InputError("<input>: lepp.triangulate takes a dict with at least 'vertices'")
    for key in ("vertex_attributes", "triangle_attributes", "triangle_max_area"):
        if key in tri and tri[key] is not None and np.size(tri[key]):
            raise ValueError(f"lepp.triangulate: '{key}' is not supported by lepp")
    if "triangles" in tri and tri["triangles"] is not None and np.size(tri["triangles"]):
        raise ValueError("lepp.triangulate: an input with 'triangles' asks to refine a mesh (switch r), "
                         "which lepp does not do; give the PSLG instead")
    sw = parse_switches(opts)
    if sw["q"] is not None and not 0 <= sw["q"] <= 60:
        raise ValueError(f"lepp.triangulate: q{sw['q']:g}: the angle bound must be in [0, 60] degrees")
    planar = sw["p"]
    pslg = pslg_dict(tri["vertices"], tri.get("segments") if planar else None, tri.get("holes") if planar else None,
                     tri.get("regions") if planar else None, tri.get("vertex_markers"),
                     tri.get("segment_markers") if planar else None)
    mesh = refine(pslg, min_angle=0.0 if sw["q"] is None else sw["q"], max_area=sw["a"], convex_hull=sw["c"],
                  region_areas=sw["a_regions"])

    n = mesh.vertices.shape[0]
    markers = np.zeros(n, dtype=np.int32)
    given = mesh._input_vertex_markers
    if given is not None and len(given) == mesh.input_vertices:
        markers[: mesh.input_vertices] = given
    boundary = _boundary_edges(mesh.triangles) if mesh.triangles.size else set()
    seg_markers = mesh.edge_markers.copy()
    for k, (a, b) in enumerate(mesh.edges):
        if seg_markers[k] == 0 and (min(a, b), max(a, b)) in boundary:
            seg_markers[k] = 1
        for v in (a, b):
            if markers[v] == 0:
                markers[v] = seg_markers[k]
    for a, b in boundary:  # without p (or with c) the boundary has no input segment
        for v in (a, b):
            if markers[v] == 0:
                markers[v] = 1
    out = {
        "vertices": mesh.vertices,
        "vertex_markers": markers.reshape(-1, 1),
        "triangles": mesh.triangles,
    }
    if planar:
        out["segments"] = mesh.edges
        out["segment_markers"] = seg_markers.reshape(-1, 1)
        for key in ("holes", "regions"):
            if key in tri and tri[key] is not None:
                out[key] = np.asarray(tri[key], dtype=float)
    return out
