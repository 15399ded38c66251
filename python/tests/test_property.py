# SPDX-License-Identifier: GPL-3.0-or-later
"""Hypothesis properties over lepp.testing's PSLG families (derandomized: a fixed seed,
no example database, so CI runs the same examples every time)."""
import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import lepp
from lepp.testing import assert_certified, degenerate_pslgs, pslgs, well_shaped_pslgs

CI = settings(derandomize=True, database=None, deadline=None, max_examples=60,
              suppress_health_check=[HealthCheck.too_slow])


@CI
@given(pslgs())
def test_generated_pslgs_are_valid(pslg):
    """Every generated PSLG passes validation untouched: no warnings (nothing merged or split)."""
    validated, warnings = lepp.validate(pslg)
    assert warnings == []
    assert validated["vertices"].shape == pslg["vertices"].shape
    assert pslg["family"].startswith("gen:")


@CI
@given(pslgs(), st.sampled_from([20, 25, 30]))
def test_refined_meshes_are_certified(pslg, theta):
    """Theorem 2 and the angle bound on any input, small input angles exempt by the certifier's rule."""
    mesh = lepp.refine(pslg, min_angle=theta, max_steiner=20000)
    if mesh.outcome in ("converged", "unimprovable"):
        assert_certified(pslg, mesh, min_angle=theta, exempt_small_input_angles=True)
    else:  # a guard stop still leaves a valid constrained Delaunay mesh
        assert_certified(pslg, mesh)


@CI
@given(well_shaped_pslgs(scale=0.25), st.sampled_from([25, 30]))
def test_well_shaped_inputs_converge(pslg, theta):
    """Remark 15's class: input angles >= 60 degrees, theta <= 30: the run converges, certified."""
    mesh = lepp.refine(pslg, min_angle=theta)
    assert mesh.outcome == "converged"
    assert_certified(pslg, mesh, min_angle=theta)


@CI
@given(degenerate_pslgs(), st.sampled_from([20, 30]))
def test_degenerate_inputs_are_certified(pslg, theta):
    """Ties, zero orientations, threshold angles, hole points on edges and vertices."""
    mesh = lepp.refine(pslg, min_angle=theta, max_steiner=20000)
    assert mesh.outcome in ("converged", "unimprovable")
    assert_certified(pslg, mesh, min_angle=theta, exempt_small_input_angles=True)


def test_assert_certified_rejects_a_broken_mesh():
    pslg = {"vertices": np.array([[0.0, 0], [4, 0], [4, 4], [0, 4]]), "segments": np.array([[0, 1], [1, 2], [2, 3], [3, 0]])}
    mesh = lepp.refine(pslg, min_angle=30).to_dict()
    assert_certified(pslg, mesh, min_angle=30)
    broken = dict(mesh, triangles=mesh["triangles"][:-1])
    with pytest.raises(AssertionError, match="not certified"):
        assert_certified(pslg, broken, min_angle=30)
    with pytest.raises(AssertionError, match="angle-below-theta"):
        assert_certified(pslg, mesh, min_angle=50)  # the square's two triangles have 45 degrees


def test_every_family_is_drawn():
    families = set()

    @settings(derandomize=True, database=None, max_examples=300)
    @given(pslgs())
    def collect(p):
        families.add(p["family"])

    collect()
    assert {"gen:convex", "gen:star", "gen:hole", "gen:cloud", "gen:cracks", "gen:wedge"} <= families
    degenerate = set()

    @settings(derandomize=True, database=None, max_examples=200)
    @given(degenerate_pslgs())
    def collect_degenerate(p):
        degenerate.add(p["family"])

    collect_degenerate()
    assert {"gen:mirror", "gen:kite", "gen:hole-on", "gen:angles"} <= degenerate
