# SPDX-License-Identifier: GPL-3.0-or-later
"""lepp.certify and lepp.render: the report of `lepp certify --json` and the SVG of
`lepp render`; broken meshes are rejected with the right reason."""
import glob
import json
import os

import numpy as np
import pytest

import lepp
from conftest import corpus, run_cli

A = corpus("paper", "A.poly")


def without_version(j):
    return {k: v for k, v in j.items() if not k.startswith("lepp_")}


@pytest.mark.parametrize("path", sorted(glob.glob(corpus("paper", "*.poly"))), ids=os.path.basename)
def test_report_is_the_cli_report(path, workdir):
    mesh = lepp.refine(path, min_angle=30)
    mesh.write(workdir / "m")
    report = lepp.certify(path, mesh, min_angle=30)
    assert report.ok and bool(report)
    assert all(c["passed"] for c in report.checks.values())
    assert report.checks["min-angle"]["run"] and not report.checks["size-bound"]["run"]
    r = run_cli("certify", path, str(workdir / "m"), "--min-angle", "30", "--json")
    assert r.returncode == 0, r.stdout
    assert without_version(json.loads(r.stdout)) == report.json
    text = run_cli("certify", path, str(workdir / "m"), "--min-angle", "30")
    assert text.stdout == report.text


def test_a_mesh_dict_from_another_mesher():
    """Only vertices and triangles: input vertices found by coordinates, constrained edges by geometry."""
    mesh = lepp.refine(A, min_angle=25)
    order = np.random.default_rng(1).permutation(mesh.vertices.shape[0])
    inverse = np.argsort(order)
    other = {"vertices": mesh.vertices[order], "triangles": inverse[mesh.triangles]}
    assert lepp.certify(A, other, min_angle=25).ok


def test_checks_reject_broken_meshes():
    mesh = lepp.refine(A, min_angle=25).to_dict()
    # Below the angle asked for: min-angle fails, the others hold.
    r = lepp.certify(A, mesh, min_angle=35)
    assert not r.ok and r.checks["min-angle"]["violations"] > 0 and r.checks["topology"]["passed"]
    assert {v["reason"] for v in r.violations} == {"angle-below-theta"}
    assert all(v["check"] == "min-angle" for v in r.violations)
    # A triangle turned clockwise.
    flipped = dict(mesh, triangles=mesh["triangles"].copy())
    flipped["triangles"][0] = flipped["triangles"][0][::-1]
    r = lepp.certify(A, flipped)
    assert not r.ok and "not-counter-clockwise" in r.counts
    # A triangle missing: a gap in the domain.
    gap = dict(mesh, triangles=mesh["triangles"][1:])
    r = lepp.certify(A, gap)
    assert not r.ok and not r.checks["topology"]["passed"]
    # A Steiner point moved: no longer Delaunay or off a segment.
    moved = dict(mesh, vertices=mesh["vertices"].copy())
    moved["vertices"][-1] += 0.3
    assert not lepp.certify(A, moved).ok
    # A size bound the mesh does not meet.
    r = lepp.certify(A, mesh, max_area=1e-3)
    assert not r.ok and r.checks["size-bound"]["run"] and r.checks["size-bound"]["violations"] > 0


def test_exempt_small_input_angles():
    path = corpus("hostile", "small-input-angle.poly")
    mesh = lepp.refine(path, min_angle=30)
    plain = {"vertices": mesh.vertices, "triangles": mesh.triangles}  # without the engine's unimprovable list
    assert not lepp.certify(path, plain, min_angle=30).ok
    r = lepp.certify(path, plain, min_angle=30, exempt_small_input_angles=True)
    assert r.ok and r.json["exempt_count"] > 0


def test_render_is_lepp_render(workdir):
    mesh = lepp.refine(A, min_angle=30)
    mesh.write(workdir / "m")
    svg = lepp.render(mesh, workdir / "py.svg")
    assert run_cli("render", str(workdir / "m"), "-o", str(workdir / "cli.svg")).returncode == 0
    with open(workdir / "cli.svg") as f:
        assert f.read() == svg
    with open(workdir / "py.svg") as f:
        assert f.read() == svg
    marked = lepp.render(mesh, triangles=[0], points=[(1.0, 1.0)], color="angle", highlight_bad=True)
    assert marked != svg and marked.startswith("<")
    with pytest.raises(ValueError):
        lepp.render({"vertices": np.zeros((0, 2)), "triangles": np.zeros((0, 3))})


def test_repr_html_is_the_cli_page(workdir):
    """Jupyter's page is the one `lepp certify --html` writes (the title apart), every kind found on it."""
    mesh = lepp.refine(A, min_angle=30)
    mesh.write(workdir / "m")
    report = lepp.certify(A, mesh, min_angle=33)
    assert not report.ok
    page = report._repr_html_()
    assert page.startswith("<!DOCTYPE html>") and 'data-certified="false"' in page
    for reason, n in report.counts.items():
        if n:
            assert f'<tr data-reason="{reason}" data-count="{n}">' in page
    r = run_cli("certify", A, str(workdir / "m"), "--min-angle", "33", "--html", str(workdir / "m.html"))
    assert r.returncode == 1, r.stdout
    cli = (workdir / "m.html").read_text()
    strip = lambda p: p[p.index('<p id="verdict"'):]  # the title and the command line differ
    assert strip(cli) == strip(page)


def test_threads_change_nothing_but_the_time(workdir):
    """threads=N (as lepp certify --threads N) gives the same report, violations in the same order."""
    mesh = lepp.refine(A, min_angle=25)
    mesh.write(workdir / "m")
    for angle in (25, 35):  # certified, then many angle violations
        one = lepp.certify(A, mesh, min_angle=angle, max_listed=5)
        for threads in (2, 3, 0):
            many = lepp.certify(A, mesh, min_angle=angle, max_listed=5, threads=threads)
            assert many.json == one.json and many.text == one.text
        cli = run_cli("certify", A, str(workdir / "m"), "--min-angle", str(angle), "--max-listed", "5", "--json", "--threads", "2")
        assert without_version(json.loads(cli.stdout)) == one.json
    with pytest.raises(ValueError):
        lepp.certify(A, mesh, threads=-1)
