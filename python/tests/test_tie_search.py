# SPDX-License-Identifier: GPL-3.0-or-later
"""tie_search_states (issue 39; docs/CERTIFIER.md section 5c): the bound of the search of
tie resolutions at the precision limit is 1024 Lepp states by default in lepp.refine,
lepp.certify and lepp.audit, as in the command, and each passes it on: to both engines,
to the certificate, to the audit's certificate and to its compared lepp engines."""
import inspect
import shutil

import lepp
from lepp import _lepp

from conftest import corpus

# At 20 degrees lepp's default search inserts through another tie resolution here, and
# leaves triangles at double precision that the certificate exempts only after following
# more than one Lepp state: a bound of one state changes both.
TIE = corpus("regressions", "precision", "tie-finding.poly")


def test_the_default_is_1024_everywhere():
    assert _lepp.TIE_SEARCH_STATES == 1024
    for call in (lepp.refine, lepp.certify, lepp.audit):
        assert inspect.signature(call).parameters["tie_search_states"].default == 1024, call.__name__
    mesh = lepp.refine(TIE, min_angle=20)
    assert mesh.statistics["tie_search_states"] == 1024
    assert lepp.certify(TIE, mesh, min_angle=20).json["tie_search_states"] == 1024


def test_refine_passes_it_to_each_engine():
    for engine in ("fast", "reference"):
        wide = lepp.refine(TIE, min_angle=20, engine=engine)
        narrow = lepp.refine(TIE, min_angle=20, engine=engine, tie_search_states=1)
        assert narrow.statistics["tie_search_states"] == 1
        assert narrow.statistics["tie_resolutions"] < wide.statistics["tie_resolutions"], engine
        assert len(narrow.vertices) != len(wide.vertices), engine


def test_certify_passes_it_to_the_certificate():
    mesh = lepp.refine(TIE, min_angle=20)
    proved = lepp.certify(TIE, mesh, min_angle=20)
    assert proved.ok, proved.text
    claims = proved.json["precision_claims"]
    assert claims and all(c["outcome"] == "exempt" for c in claims)
    bounded = lepp.certify(TIE, mesh, min_angle=20, tie_search_states=1)
    assert not bounded.ok
    assert bounded.json["tie_search_states"] == 1 and bounded.json["precision_undecided"] > 0
    assert "stopped undecided at bound 1 Lepp states" in bounded.text
    timed = lepp.certify(TIE, mesh, min_angle=20, tie_search_states=0, time_limit=1e-9)
    assert all(c.get("undecided") == "time-limit" for c in timed.json["precision_claims"]), timed.json["precision_claims"]


def test_audit_passes_it_to_its_certificate_and_compared_engines(tmp_path):
    inputs = tmp_path / "inputs"
    inputs.mkdir()
    shutil.copy(TIE, inputs)

    def engine(pslg, theta):  # lepp at its default bound
        return lepp.refine(pslg, min_angle=theta)

    def run(states):
        return lepp.audit(engine, theta=20, cases=1, sources=[], inputs=[inputs], compare=["fast"], shrink=False,
                          out=tmp_path / f"out-{states}", tie_search_states=states)

    wide, narrow = run(1024), run(1)
    assert wide.json["tie_search_states"] == 1024 and narrow.json["tie_search_states"] == 1
    assert wide.rows["min-angle"]["held"] == 1, wide.markdown
    assert narrow.rows["min-angle"]["failed"] == 1, narrow.markdown  # undecided at one state: no exemption
    # The compared fast engine ran at the bound: at the default it makes the audited mesh (ratio 1).
    assert wide.json["points_ratio"][0]["total"] == 1
    assert narrow.json["points_ratio"][0]["total"] != 1
