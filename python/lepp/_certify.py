# SPDX-License-Identifier: GPL-3.0-or-later
"""lepp.certify: the exact certifier (docs/CERTIFIER.md) on any mesher's mesh."""
from . import _lepp
from ._convert import mesh_dict, pslg_dict

# The seven checks, in the certifier's order, and the reasons each can fail with.
_REASONS = _lepp.certify_checks()
CHECKS = list(dict.fromkeys(check for _, check in _REASONS))


class Report:
    """The certificate of one mesh.

    ok          every check that was run passed (lepp certify's exit status 0)
    checks      {check: {'run': bool, 'passed': bool, 'violations': count}} for the seven
                checks (topology, input-vertices, constrained-edges, delaunay, min-angle,
                theorem-2, size-bound); min-angle runs with min_angle > 0, size-bound with
                max_area or region_areas
    violations  list of dicts (reason, check, message, triangles, edges, vertices, points,
                segment, region; ids 0-based), at most max_listed per reason
    counts      {reason: count}, every violation counted
    statistics  dict (vertices, triangles, min_angle, avg_min_angle, ...)
    json        the whole report, as `lepp certify --json` prints it
    text        the report as `lepp certify` prints it
    warnings    what validating the input repaired
    """

    def __init__(self, report, text, warnings, ran, page_args=None):
        self._page_args = page_args
        self.json = report
        self.ok = bool(report["certified"])
        self.violations = report["violations"]
        self.counts = dict(report["violation_counts"])
        self.statistics = report["statistics"]
        self.text = text
        self.warnings = list(warnings)
        per_check = {c: 0 for c in CHECKS}
        for reason, check in _REASONS:
            per_check[check] += self.counts.get(reason, 0)
        self.checks = {c: {"run": ran[c], "passed": per_check[c] == 0, "violations": per_check[c]} for c in CHECKS}

    def __bool__(self):
        return self.ok

    def __repr__(self):
        bad = sum(self.counts.values())
        return f"<lepp.Report {'certified' if self.ok else f'{bad} violations'}>"

    def html(self):
        """The certificate as `lepp certify --html` writes it: one self-contained HTML page
        (the mesh and each violation as pictures that pan and zoom). Certifies again."""
        if self._page_args is None:
            raise ValueError("this report has no mesh to draw")
        args, kwargs = self._page_args
        return _lepp.certify_html(*args, **kwargs)

    def _repr_html_(self):
        """Jupyter shows the report as its HTML page."""
        return self.html()


def certify(pslg, mesh, *, min_angle=0, exempt_small_input_angles=False, conforming=False, theorem2=True,
            max_area=None, region_areas=False, convex_hull=False, split_crossings=False, max_listed=50,
            unimprovable=None, tie_search_states=_lepp.TIE_SEARCH_STATES, time_limit=None, threads=1):
    """Certifies a mesh of a PSLG exactly, as `lepp certify` does.

    pslg: a PSLG dict, a path, or a (vertices, segments[, holes[, regions]]) tuple.
    mesh: a lepp.Mesh or a dict with vertices (n, 2), triangles (m, 3) and optionally
    edges (the constrained edges) and input_vertices. A lepp.Mesh's unimprovable
    triangles are passed on (they are exempt when the rule of ALGORITHM.md section 8
    holds for them). Returns a lepp.Report; bad input raises InputError.
    tie_search_states: the bound, in Lepp states, of the search that decides a triangle listed
    as left at double precision (exempt, rejected with a witness, or undecided at the bound;
    as `lepp certify --tie-search-states`; 0: no bound). time_limit: seconds for those
    searches in all (None: no limit).
    threads: as `lepp certify --threads` (0: the machine's cores); the report is the same
    for any count.
    """
    if isinstance(pslg, tuple):
        pslg = pslg_dict(*pslg)
    else:
        pslg = pslg_dict(pslg)
    if unimprovable is None:
        unimprovable = getattr(mesh, "unimprovable", [])
    args = (pslg, mesh_dict(mesh))
    kwargs = dict(min_angle=float(min_angle), conforming=bool(conforming), theorem2=bool(theorem2),
                  exempt_small_input_angles=bool(exempt_small_input_angles),
                  max_area=0.0 if max_area is None else float(max_area), region_areas=bool(region_areas),
                  max_listed=int(max_listed), convex_hull=bool(convex_hull), split_crossings=bool(split_crossings),
                  unimprovable=list(unimprovable), tie_search_states=int(tie_search_states),
                  time_limit=0.0 if time_limit is None else float(time_limit))
    report, text, warnings = _lepp.certify(*args, **kwargs, threads=int(threads))
    ran = {c: True for c in CHECKS}
    ran["min-angle"] = min_angle > 0
    ran["theorem-2"] = bool(theorem2)
    ran["size-bound"] = max_area is not None and max_area > 0 or bool(region_areas)
    return Report(report, text, warnings, ran, (args, dict(kwargs, title="lepp.certify")))
