# SPDX-License-Identifier: GPL-3.0-or-later
"""lepp: Lepp-centroid quality triangulation, its exact certifier and the audit, from Python.

    import lepp
    mesh = lepp.refine(vertices, segments, min_angle=30)       # a lepp.Mesh (NumPy arrays)
    report = lepp.certify((vertices, segments), mesh, min_angle=30)
    assert report.ok, report.text
    lepp.render(mesh, "mesh.svg")
    mesh.write("mesh.vtu")                                     # .vtu, .msh or Triangle's files, by extension
    lepp.plot(mesh)                                            # matplotlib; mesh.to_meshio(), lepp.from_meshio
    lepp.audit(my_mesher, theta=(20, 25, 30), cases=60)        # any Python mesher, against the paper

lepp.triangulate(tri, 'pq30a0.1') takes and returns the `triangle` package's dicts.
Bad input raises lepp.InputError (a ValueError) with the message `lepp refine` prints.
docs/PYTHON.md in the source tree describes every call.
"""
import os

from . import _lepp
from ._audit import AuditReport, audit
from ._certify import Report, certify
from ._convert import mesh_dict as _mesh_dict
from ._convert import pslg_dict as _pslg_dict
from ._mesh import Mesh
from ._meshio import from_meshio
from ._plot import plot
from .triangle_api import triangulate

__version__ = _lepp.__version__
InputError = _lepp.InputError

__all__ = ["InputError", "Mesh", "Report", "AuditReport", "refine", "certify", "render", "plot", "audit", "triangulate",
           "read_poly", "validate", "from_meshio", "__version__"]


def read_poly(path):
    """Reads a .poly, a .node or a bare prefix as `lepp refine` does; returns a PSLG dict
    (vertices, segments, segment_markers, vertex_markers, holes, regions: 0-based NumPy arrays).
    InputError names the file and line of what is wrong."""
    pslg, _warnings = _lepp.read_input(os.fspath(path))
    return pslg


def validate(vertices, segments=None, holes=None, regions=None, *, convex_hull=False, split_crossings=False):
    """The PSLG as the engines see it (duplicate vertices merged, segments split at vertices on
    them, ...): (PSLG dict, warnings). InputError when it is no PSLG (crossing segments, ...)."""
    return _lepp.validate(_pslg_dict(vertices, segments, holes, regions), convex_hull, split_crossings)


def refine(vertices, segments=None, holes=None, regions=None, *, min_angle=30, max_area=None, method="centroid",
           order="fifo", engine="fast", max_steiner=None, time_limit=None, convex_hull=False, split_crossings=False,
           trace=False, region_areas=False, edge_floor=None, vertex_markers=None, segment_markers=None,
           order_seed=0, threads=0, tie_search_states=_lepp.TIE_SEARCH_STATES):
    """Refines a PSLG into a constrained Delaunay mesh with no angle below min_angle, as
    `lepp refine` does (same engines, same mesh), and returns a lepp.Mesh.

    vertices: (n, 2) coordinates, or a PSLG dict (the `triangle` package's keys), or the path
    of a .poly / .node file. segments: (m, 2) 0-based vertex ids. holes: (h, 2) points.
    regions: (r, 4) rows x, y, attribute, max_area (applied with region_areas=True).
    A guard stop (max_steiner, time_limit, the edge floor) is an outcome (mesh.outcome), not
    an exception; bad input raises InputError. The GIL is released while the engine runs.
    order_seed: the seed of order="random" (as `lepp refine --order-seed`; other orders ignore it).
    threads: the threads of order="batch"'s selection (as `lepp refine --threads`; 0: the machine's
    cores). The mesh is the same for every number; the other orders run on one.
    tie_search_states: at the precision limit, the Lepp states per triangle searched for another
    resolution of exact length ties before the triangle is left (as `lepp refine
    --tie-search-states`; 0: no bound).
    """
    pslg = _pslg_dict(vertices, segments, holes, regions, vertex_markers, segment_markers)
    result = _lepp.refine(
        pslg,
        min_angle=float(min_angle),
        max_area=0.0 if max_area is None else float(max_area),
        region_areas=bool(region_areas),
        method=method,
        order=order,
        engine=engine,
        max_steiner=-1 if max_steiner is None else int(max_steiner),
        edge_floor=-1.0 if edge_floor is None else float(edge_floor),
        time_limit=0.0 if time_limit is None else float(time_limit),
        convex_hull=bool(convex_hull),
        split_crossings=bool(split_crossings),
        trace=bool(trace),
        order_seed=int(order_seed),
        threads=int(threads),
        tie_search_states=int(tie_search_states),
    )
    return Mesh(result)


def render(mesh, path=None, *, color="quality", highlight_bad=False, min_angle=30, width=1000, title="",
           triangles=(), points=()):
    """Draws a mesh (a lepp.Mesh or a mesh dict) as `lepp render` does and writes the SVG to
    path (when given); returns the SVG text. triangles and points are highlighted in red."""
    svg = _lepp.render_svg(_mesh_dict(mesh), color, bool(highlight_bad), float(min_angle), float(width), title,
                           [int(t) for t in triangles], [(float(x), float(y)) for x, y in points])
    if path is not None:
        with open(os.fspath(path), "w") as f:
            f.write(svg)
    return svg
