# SPDX-License-Identifier: GPL-3.0-or-later
"""Bad input never crashes the interpreter: every file of corpus/bad raises
lepp.InputError (a ValueError) with the message `lepp refine` prints, naming the file
and line; malformed arrays raise it too."""
import glob
import os

import numpy as np
import pytest

import lepp
from conftest import corpus, run_cli

BAD = sorted(glob.glob(corpus("bad", "*")))
BAD = [p for p in BAD if p.endswith((".poly", ".node"))]


def test_there_are_bad_files():
    assert len(BAD) >= 30


@pytest.mark.parametrize("path", BAD, ids=os.path.basename)
def test_bad_file_raises_input_error_with_the_cli_message(path, workdir):
    r = run_cli("refine", path, "-o", str(workdir / "m"), "-q")
    assert r.returncode == 2, r.stderr
    with pytest.raises(lepp.InputError) as e:
        lepp.refine(path, min_angle=25)
    assert isinstance(e.value, ValueError)
    assert "lepp refine: " + str(e.value) in r.stderr.splitlines()
    assert e.value.file  # the file it names
    assert os.path.basename(path) in str(e.value) or "node" in str(e.value)


@pytest.mark.parametrize("path", BAD, ids=os.path.basename)
def test_bad_file_through_certify(path):
    """The same error from lepp.certify, which reads and validates the input too."""
    mesh = {"vertices": np.array([[0.0, 0], [1, 0], [0, 1]]), "triangles": np.array([[0, 1, 2]])}
    with pytest.raises(lepp.InputError):
        lepp.certify(path, mesh)


@pytest.mark.parametrize("vertices,segments,message", [
    ([[0, 0], [1, 0], [float("nan"), 1]], None, "not finite"),
    ([[0, 0], [1, 0], [float("inf"), 1]], None, "not finite"),
    ([[0, 0], [1, 0], [2, 0]], None, ""),                                  # collinear
    ([[0, 0], [1, 0]], None, ""),                                          # too few
    ([[0, 0], [1, 0], [0, 1]], [[0, 3]], "out of range"),
    ([[0, 0], [1, 0], [0, 1]], [[0, -1]], "out of range"),
    ([[0, 0], [2, 2], [2, 0], [0, 2]], [[0, 1], [2, 3]], "cross"),
    ([[0, 0, 0], [1, 0, 0], [0, 1, 0]], None, "shape"),
    ([[0, 0], [1, 0], [0, 1]], [[0.5, 1]], "integers"),
    ([[0, 0], [1, 0], [0, 1]], [[0, 1, 2]], "shape"),
    ([["a", "b"], ["c", "d"], ["e", "f"]], None, "numbers"),
    ([], None, ""),
])
def test_bad_arrays(vertices, segments, message):
    with pytest.raises(lepp.InputError, match=message) as e:
        lepp.refine(vertices, segments)
    assert str(e.value).startswith("<input>")


def test_ragged_and_wrong_keys():
    with pytest.raises(lepp.InputError):
        lepp.refine([[0, 0], [1], [0, 1]])
    with pytest.raises(lepp.InputError, match="vertices"):
        lepp.refine({"points": [[0, 0], [1, 0], [0, 1]]})
    with pytest.raises(lepp.InputError, match="marker"):
        lepp.refine([[0, 0], [1, 0], [0, 1]], [[0, 1]], segment_markers=[1, 2])
    with pytest.raises(TypeError):
        lepp.refine(corpus("paper", "A.poly"), [[0, 1]])


def test_duplicates_are_warnings_not_errors():
    mesh = lepp.refine([[0, 0], [1, 0], [0, 1], [1, 0]], min_angle=20)
    assert any("duplicate" in w for w in mesh.warnings)
    assert mesh.input_vertices == 3


def test_missing_file_is_input_error():
    with pytest.raises(lepp.InputError, match="no-such-file"):
        lepp.refine("no-such-file.poly")


def test_zero_length_segment_is_dropped_not_an_error():
    # As Triangle does (issue 20): the segment from a vertex to itself is dropped with a warning.
    mesh = lepp.refine([[0, 0], [1, 0], [0, 1]], [[0, 1], [1, 2], [2, 0], [1, 1]])
    assert mesh.outcome in ("converged", "unimprovable")
