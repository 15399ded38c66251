# SPDX-License-Identifier: GPL-3.0-or-later
"""lepp.audit: a Python mesher audited in process against the paper's statements,
by the loop behind `lepp audit` (docs/AUDIT.md): the same inputs, rows, shrinking,
findings on disk and report."""
import inspect
import os

import numpy as np

from . import _lepp
from ._convert import mesh_dict


class AuditReport:
    """The audit's outcome.

    holds      every row held (lepp audit's exit status 0)
    rows       {row: dict} for certificate, min-angle, theorem-2, termination, conformance:
               runs, held, failed, findings, not_applicable, not_checked, holds, first (the
               first failure seen), counterexamples (each: dir with input.poly, out.*,
               finding.svg, finding.md; the shrunk input's size; detail)
    markdown   the report `lepp audit` prints
    json       the report `lepp audit --json` prints
    html       the page `lepp audit --html` writes (Jupyter shows it: _repr_html_)
    """

    def __init__(self, report, markdown, status, html=""):
        self.json = report
        self.markdown = markdown
        self.html = html
        self.holds = status == 0
        self.rows = {r["check"]: r for r in report["rows"]}

    def __bool__(self):
        return self.holds

    def __str__(self):
        return self.markdown

    def _repr_html_(self):
        return self.html

    def __repr__(self):
        failed = [k for k, r in self.rows.items() if not r["holds"]]
        return f"<lepp.AuditReport {'every row holds' if self.holds else 'failed: ' + ', '.join(failed)}>"


def _adapter(engine):
    """The user's engine(pslg, theta) -> mesh as the extension calls it: (pslg, theta,
    method, work_dir) -> a plain mesh dict. The engine may also take keyword arguments
    method and work_dir, and may return a lepp.Mesh, a dict (vertices, triangles, and
    optionally trace (s, 2), edges, input_vertices, stopped: why it stopped early), or a
    (vertices, triangles[, trace]) tuple."""
    try:
        params = inspect.signature(engine).parameters
    except (TypeError, ValueError):
        params = {}
    wants = {k for k in ("method", "work_dir") if k in params or any(
        p.kind == inspect.Parameter.VAR_KEYWORD for p in params.values())}

    def call(pslg, theta, method, work_dir):
        kwargs = {}
        if "method" in wants:
            kwargs["method"] = method
        if "work_dir" in wants:
            kwargs["work_dir"] = work_dir
        out = engine(pslg, theta, **kwargs)
        if isinstance(out, tuple):
            out = dict(zip(("vertices", "triangles", "trace"), out))
        trace = out.trace if hasattr(out, "_arrays") else out.get("trace")
        stopped = None if hasattr(out, "_arrays") else out.get("stopped")
        if hasattr(out, "_arrays") and not out.converged and out.outcome != "unimprovable":
            stopped = out.outcome
        d = mesh_dict(out)
        if trace is not None:
            d["trace"] = np.ascontiguousarray(np.asarray(trace, dtype=np.float64).reshape(-1, 2))
        if stopped:
            d["stopped"] = str(stopped)
        return d

    return call


def audit(engine, theta=(20, 25, 30), cases=300, *, method="centroid", seed=1, sources=("gen", "paper", "corpus"),
          inputs=(), root=None, out="audit-out", compare=(), timeout=None, angle_tolerance=1e-3,
          point_tolerance=8, shrink=True, max_findings=3, shrink_seconds=60, junit=None, name=None,
          tie_search_states=_lepp.TIE_SEARCH_STATES):
    """Audits engine, a Python mesher: engine(pslg, theta) gets a validated PSLG dict
    (vertices, segments, holes, ...: NumPy arrays, 0-based) and the smallest angle wanted in
    degrees, and returns the mesh (a dict with vertices (n, 2) and triangles (m, 3) and, for
    the conformance row, trace: the Steiner points in insertion order; or a lepp.Mesh).

    The rows, the inputs (RapidCheck's PSLG families for seed; corpus/paper and corpus/hostile
    found as `lepp audit` finds them: under root when given, else share/lepp of the installed
    package, else the source tree lepp was built from; a source asked for and not found raises
    ValueError, never a silent skip), the shrinking of each failure through the engine and the
    findings saved under out are those of `lepp audit`. An exception in the engine is a
    crashed run (its traceback kept with the finding), not the end of the audit;
    KeyboardInterrupt stops it. In process nothing can stop a run: with timeout (seconds) a
    run that returns later counts as timed out. compare: 'reference', 'fast' (points added,
    against lepp's engines). tie_search_states: the certificate's precision-limit search bound,
    and lepp's compared engines' (as `lepp audit --tie-search-states`; 0: no bound).
    Returns a lepp.AuditReport.
    """
    if callable(engine) is False:
        raise TypeError("engine: a callable engine(pslg, theta) -> mesh dict")
    thetas = [float(theta)] if np.isscalar(theta) else [float(t) for t in theta]
    if isinstance(sources, str):
        sources = sources.split(",")
    if isinstance(inputs, (str, os.PathLike)):
        inputs = [inputs]
    if isinstance(compare, str):
        compare = [compare]
    if name is None:
        name = getattr(engine, "__qualname__", None) or getattr(engine, "__name__", None) or repr(engine)
    sources = list(sources)
    # None: the C++ side finds the corpus as `lepp audit` does (data_root.h); a built-in
    # source that is not there is a ValueError naming it, never a silent skip.
    if root is None:
        # The Debian layout: usr/lib/python3/dist-packages/lepp beside usr/share/lepp.
        installed = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "..", "share", "lepp")
        root = os.path.normpath(installed) if os.path.isdir(os.path.join(installed, "corpus")) else ""
    root = os.fspath(root)
    report, markdown, status, html = _lepp.audit(
        _adapter(engine), name=name, method=method, thetas=thetas, cases=int(cases), seed=int(seed),
        sources=sources, inputs=[os.fspath(i) for i in inputs], compare=list(compare), root=root,
        out=os.fspath(out), junit="" if junit is None else os.fspath(junit),
        timeout=0.0 if timeout is None else float(timeout), angle_tolerance=float(angle_tolerance),
        point_tolerance=float(point_tolerance), shrink=bool(shrink), max_findings=int(max_findings),
        shrink_seconds=float(shrink_seconds), tie_search_states=int(tie_search_states))
    return AuditReport(report, markdown, status, html)
