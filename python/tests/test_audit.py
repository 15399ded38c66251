# SPDX-License-Identifier: GPL-3.0-or-later
"""lepp.audit of Python meshers in process: lepp's own engine called from Python holds
every row (conformance too, from its trace); a seeded bug is found, shrunk and saved; an
engine that raises is a crashed run, not the end of the audit."""
import os

import numpy as np
import pytest

import lepp

QUICK = dict(cases=45, sources=["gen"], max_findings=1, shrink_seconds=20)


def correct(pslg, theta):
    return lepp.refine(pslg, min_angle=theta, trace=True)


def skips_refinement_on_larger_inputs(pslg, theta):
    """Seeded bug: inputs of more than 12 vertices are refined 8 degrees short of theta."""
    short = theta - 8 if pslg["vertices"].shape[0] > 12 else theta
    mesh = lepp.refine(pslg, min_angle=short, trace=True)
    return {"vertices": mesh.vertices, "triangles": mesh.triangles, "trace": mesh.trace}


def test_a_correct_python_mesher_holds(tmp_path):
    report = lepp.audit(correct, theta=(20, 30), out=tmp_path / "out", **QUICK)
    assert report.holds, report.markdown
    assert report.rows["conformance"]["held"] > 0  # the trace came through and was replayed
    assert report.rows["min-angle"]["held"] > 0
    assert report.json["runs"] == 45 and "| certificate" in report.markdown


def test_a_seeded_bug_is_found_and_shrunk(tmp_path):
    out = tmp_path / "out"
    report = lepp.audit(skips_refinement_on_larger_inputs, theta=(25, 30), out=out, junit=tmp_path / "j.xml",
                        **QUICK)
    assert not report.holds
    row = report.rows["min-angle"]
    assert row["failed"] > 0 and row["counterexamples"]
    cx = row["counterexamples"][0]
    assert cx["vertices"] <= cx["original_vertices"]
    assert cx["vertices"] > 12  # the bug's condition survives shrinking: below it the mesher is right
    assert os.path.exists(os.path.join(cx["dir"], "input.poly"))
    assert os.path.exists(os.path.join(cx["dir"], "finding.svg"))
    # The shrunk input reproduces it: read back and run the mesher directly.
    pslg = lepp.read_poly(os.path.join(cx["dir"], "input.poly"))
    bad = skips_refinement_on_larger_inputs(pslg, cx["theta"])
    assert not lepp.certify(pslg, bad, min_angle=cx["theta"], exempt_small_input_angles=True).ok
    assert "failures=\"" in (tmp_path / "j.xml").read_text()
    # The page Jupyter shows: the row with its counts, each saved finding with its pictures.
    page = report._repr_html_()
    assert page.startswith("<!DOCTYPE html>") and 'data-holds="false"' in page
    assert f'<tr data-row="min-angle" data-runs="{row["runs"]}" data-held="{row["held"]}" data-failed="{row["failed"]}"' in page
    saved = sum(len(r["counterexamples"]) for r in report.rows.values())
    assert page.count('<section class="finding"') == saved
    assert page.count('class="pz picture"') >= 2 * saved  # the input and the mesh around the violation, at least


def test_an_engine_that_raises_is_a_crashed_run(tmp_path):
    calls = []

    def flaky(pslg, theta):
        calls.append(1)
        if len(calls) % 2:
            raise RuntimeError("seeded failure")
        return correct(pslg, theta)

    report = lepp.audit(flaky, theta=25, cases=6, sources="gen", out=tmp_path / "out", shrink=False)
    assert report.json["run_status"]["crashed"] >= 3
    assert not report.holds
    assert "seeded failure" in report.rows["certificate"]["first"] or "seeded failure" in report.markdown


def test_engine_gets_method_and_work_dir_when_it_asks(tmp_path):
    seen = []

    def engine(pslg, theta, method, work_dir):
        seen.append((method, os.path.isdir(work_dir)))
        return lepp.refine(pslg, min_angle=theta, method=method, trace=True)

    report = lepp.audit(engine, theta=20, cases=4, sources="gen", method="midpoint", out=tmp_path / "out")
    assert report.holds, report.markdown
    assert seen and all(m == "midpoint" and d for m, d in seen)


def test_bad_usage_raises():
    with pytest.raises(ValueError):
        lepp.audit(correct, sources=["nowhere"], cases=1)
    with pytest.raises(TypeError):
        lepp.audit("not a function", cases=1)


def test_built_in_sources_are_found_from_any_directory(tmp_path, monkeypatch):
    # No root: the corpus is found as `lepp audit` finds it (share/lepp, else the source
    # tree), not relative to the working directory.
    monkeypatch.chdir(tmp_path)
    report = lepp.audit(correct, theta=20, cases=2, sources=["paper"], out=tmp_path / "out", shrink=False)
    assert report.json["runs"] == 2, report.markdown
    assert report.holds, report.markdown


def test_a_missing_built_in_source_is_an_error_not_a_skip(tmp_path):
    with pytest.raises(ValueError, match="built-in source paper"):
        lepp.audit(correct, theta=20, cases=2, sources=["gen", "paper"], root=tmp_path, out=tmp_path / "out")
