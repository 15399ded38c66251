# SPDX-License-Identifier: GPL-3.0-or-later
"""Shared by the Python tests: where the source tree and the lepp command are
(LEPP_SOURCE_DIR, LEPP_CLI: set by ctest), and reading a mesh lepp refine wrote."""
import os
import subprocess

import numpy as np
import pytest

SOURCE = os.environ.get("LEPP_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
CLI = os.environ.get("LEPP_CLI", "lepp")


def corpus(*parts):
    return os.path.join(SOURCE, "corpus", *parts)


def run_cli(*args):
    return subprocess.run([CLI, *args], capture_output=True, text=True)


def read_triangle_mesh(prefix):
    """PREFIX.node and PREFIX.ele (1-based) as (vertices, triangles, node markers), parsed by hand."""
    def rows(path):
        with open(path) as f:
            lines = [l.split("#")[0].split() for l in f]
        return [l for l in lines if l]
    node = rows(prefix + ".node")
    n = int(node[0][0])
    v = np.array([[float(r[1]), float(r[2])] for r in node[1:n + 1]])
    markers = np.array([int(r[3]) for r in node[1:n + 1]])
    ele = rows(prefix + ".ele")
    m = int(ele[0][0])
    t = np.array([[int(x) - 1 for x in r[1:4]] for r in ele[1:m + 1]], dtype=np.int32).reshape(-1, 3)
    return v, t, markers


@pytest.fixture
def workdir(tmp_path):
    return tmp_path
