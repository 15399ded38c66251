# SPDX-License-Identifier: GPL-3.0-or-later
"""What users pass in, turned into the arrays the extension reads.

A PSLG is given as arrays (vertices (n, 2), segments (m, 2) 0-based, holes
(h, 2), regions (r, 4): x, y, attribute, max_area), as the `triangle`
package's dict with those keys, or as the path of a .poly / .node file (read
as `lepp refine` reads it). Anything malformed raises InputError with a
message that names the array and what is wrong.
"""
import os

import numpy as np

from . import _lepp

InputError = _lepp.InputError


def _table(name, value, columns, dtype):
    if value is None:
        return np.zeros((0, columns), dtype=dtype)
    try:
        a = np.asarray(value)
    except (TypeError, ValueError) as e:  # ragged lists and the like
        raise InputError(f"<input>: {name}: not an array ({e})") from None
    if a.size == 0:
        return np.zeros((0, columns), dtype=dtype)
    if a.ndim == 1 and a.shape[0] == columns:
        a = a.reshape(1, columns)
    if a.ndim != 2 or a.shape[1] != columns:
        raise InputError(f"<input>: {name}: expected shape (n, {columns}), got {a.shape}")
    if np.issubdtype(dtype, np.integer):
        if not np.issubdtype(a.dtype, np.integer):
            if not np.issubdtype(a.dtype, np.number) or not np.all(np.isfinite(a)) or np.any(a != np.round(a)):
                raise InputError(f"<input>: {name}: vertex ids must be integers")
        if a.size and (a.min() < np.iinfo(np.int32).min or a.max() > np.iinfo(np.int32).max):
            raise InputError(f"<input>: {name}: a vertex id out of range")
    elif not np.issubdtype(a.dtype, np.number):
        raise InputError(f"<input>: {name}: expected numbers, got {a.dtype}")
    return np.ascontiguousarray(a, dtype=dtype)


def _markers(name, value, count):
    if value is None:
        return None
    a = np.asarray(value)
    if a.size == 0 and count > 0:  # none given (the triangle package's empty markers)
        return None
    if a.ndim == 2 and a.shape[1] == 1:
        a = a[:, 0]
    if a.ndim != 1 or a.shape[0] != count:
        raise InputError(f"<input>: {name}: expected one marker per item ({count}), got shape {a.shape}")
    if a.size and not np.issubdtype(a.dtype, np.integer):
        if not np.all(np.isfinite(a)) or np.any(a != np.round(a)):
            raise InputError(f"<input>: {name}: markers must be integers")
    return np.ascontiguousarray(a, dtype=np.int32)


def _regions(value):
    """Regions as (r, 4); the `triangle` package also takes (r, 3) (no area bound) rows."""
    if value is None:
        return np.zeros((0, 4))
    a = np.asarray(value, dtype=float) if len(value) else np.zeros((0, 4))
    if a.ndim == 2 and a.shape[1] == 3:
        a = np.hstack([a, np.full((a.shape[0], 1), -1.0)])
    return _table("regions", a, 4, np.float64)


def pslg_dict(vertices, segments=None, holes=None, regions=None, vertex_markers=None, segment_markers=None):
    """The extension's PSLG dict from any accepted form (see the module docstring)."""
    if isinstance(vertices, (str, os.PathLike)):
        if any(x is not None for x in (segments, holes, regions, vertex_markers, segment_markers)):
            raise TypeError("a file path already gives segments, holes and regions: pass nothing else")
        pslg, _ = _lepp.read_input(os.fspath(vertices))
        return pslg
    if isinstance(vertices, dict):
        if any(x is not None for x in (segments, holes, regions, vertex_markers, segment_markers)):
            raise TypeError("a PSLG dict already gives segments, holes and regions: pass nothing else")
        d = vertices
        if "vertices" not in d:
            raise InputError("<input>: the PSLG dict has no 'vertices'")
        out = pslg_dict(d["vertices"], d.get("segments"), d.get("holes"), d.get("regions"),
                        d.get("vertex_markers"), d.get("segment_markers"))
        # A PSLG read from a file (lepp.read_poly) keeps its file and lines for messages.
        for key in ("source", "vertex_lines", "segment_lines", "hole_lines", "region_lines"):
            if d.get(key) is not None:
                out[key] = d[key]
        return out
    v = _table("vertices", vertices, 2, np.float64)
    s = _table("segments", segments, 2, np.int32)
    out = {
        "vertices": v,
        "segments": s,
        "holes": _table("holes", holes, 2, np.float64),
        "regions": _regions(regions),
        "source": "<input>",
    }
    vm = _markers("vertex_markers", vertex_markers, v.shape[0])
    if vm is not None:
        out["vertex_markers"] = vm
    sm = _markers("segment_markers", segment_markers, s.shape[0])
    if sm is not None:
        out["segment_markers"] = sm
    return out


def mesh_dict(mesh):
    """The extension's mesh dict from a lepp.Mesh or any dict with vertices and triangles
    (and optionally edges / segments, the constrained edges, and input_vertices)."""
    if hasattr(mesh, "_arrays"):
        return mesh._arrays()
    if not isinstance(mesh, dict) or "vertices" not in mesh or "triangles" not in mesh:
        raise TypeError("a mesh is a lepp.Mesh or a dict with 'vertices' and 'triangles'")
    out = {
        "vertices": _table("vertices", mesh["vertices"], 2, np.float64),
        "triangles": _table("triangles", mesh["triangles"], 3, np.int32),
    }
    edges = mesh.get("edges", mesh.get("segments"))
    if edges is not None:
        out["edges"] = _table("edges", edges, 2, np.int32)
        ids = mesh.get("edge_segments")
        if ids is not None:
            out["edge_segments"] = _markers("edge_segments", ids, out["edges"].shape[0])
    if mesh.get("input_vertices") is not None:
        out["input_vertices"] = int(mesh["input_vertices"])
    return out
