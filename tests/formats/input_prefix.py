#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""A bare input prefix through the CLI, as Triangle takes one (docs/FORMATS.md).

`lepp refine X` and `lepp certify X MESH` read X.poly, else X.node, when X
itself is no file: the mesh is the one the full name gives, the .poly wins
over the .node, and with neither the command exits 2 with one line naming X,
X.poly and X.node. An output prefix that would write over the input is
refused (exit 2, one line naming the file). Needs no Triangle.

usage: input_prefix.py LEPP SOURCE_DIR SCRATCH_DIR
Exit 0 all pass, 1 a failure (each printed).
"""
import os
import shutil
import sys

from formats_check import fail, failures, run


def mesh_files(prefix):
    """The bytes of PREFIX.node/.ele/.poly, to compare two runs' meshes."""
    out = []
    for ext in (".node", ".ele", ".poly"):
        with open(prefix + ext, "rb") as f:
            out.append(f.read())
    return out


def refine(lepp, path, out):
    r = run([lepp, "refine", path, "-o", out, "-q"])
    if r.returncode != 0:
        fail(f"lepp refine {path}: exit {r.returncode}: {r.stderr.strip()}")
        return None
    return mesh_files(out)


def expect_missing(lepp, command, prefix):
    """Exit 2, one line on stderr naming the prefix and both files tried."""
    r = run(command)
    lines = r.stderr.strip().splitlines()
    named = all(n in r.stderr for n in (prefix + ":", prefix + ".poly", prefix + ".node"))
    if r.returncode != 2 or len(lines) != 1 or not named:
        fail(f"{' '.join(command[1:3])} on a missing prefix: expected exit 2 and one line naming "
             f"{prefix}, .poly and .node; got {r.returncode}: {r.stderr.strip()}")
    else:
        print(f"missing prefix, {command[1]}: exit 2: {lines[0]}")


def main():
    lepp, source, scratch = sys.argv[1:4]
    corpus = os.path.join(source, "corpus", "triangle-formats")
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    poly_src = os.path.join(corpus, "zero-based.poly")
    node_src = os.path.join(corpus, "points.node")

    # The full names' meshes, to compare against.
    by_poly = refine(lepp, poly_src, os.path.join(scratch, "full-poly"))
    by_node = refine(lepp, node_src, os.path.join(scratch, "full-node"))
    if by_poly is None or by_node is None:
        return 1
    if by_poly == by_node:
        fail("the .poly and the .node give the same mesh: the cases below could not tell them apart")

    # prefix -> .poly
    only_poly = os.path.join(scratch, "only-poly")
    shutil.copy(poly_src, only_poly + ".poly")
    if refine(lepp, only_poly, only_poly + "-out") != by_poly:
        fail("refine PREFIX with only PREFIX.poly: not the mesh of the .poly")
    else:
        print("prefix with only PREFIX.poly: the .poly's mesh")

    # prefix -> .node when only the .node exists
    only_node = os.path.join(scratch, "only-node")
    shutil.copy(node_src, only_node + ".node")
    if refine(lepp, only_node, only_node + "-out") != by_node:
        fail("refine PREFIX with only PREFIX.node: not the mesh of the .node")
    else:
        print("prefix with only PREFIX.node: the .node's mesh")

    # .poly preferred when both exist
    both = os.path.join(scratch, "both")
    shutil.copy(poly_src, both + ".poly")
    shutil.copy(node_src, both + ".node")
    if refine(lepp, both, both + "-out") != by_poly:
        fail("refine PREFIX with PREFIX.poly and PREFIX.node: not the mesh of the .poly")
    else:
        print("prefix with both: the .poly's mesh")

    # -o naming the input's own prefix would write over the input: exit 2, one
    # line naming the file, the input unchanged (a prefix, a full name, a .node).
    for inp, out, victim in ((both, both, both + ".poly"), (both + ".poly", both, both + ".poly"),
                             (only_node + ".node", only_node, only_node + ".node")):
        before = open(victim, "rb").read()
        r = run([lepp, "refine", inp, "-o", out, "-q"])
        lines = r.stderr.strip().splitlines()
        if r.returncode != 2 or len(lines) != 1 or victim not in lines[0] or open(victim, "rb").read() != before:
            fail(f"refine {inp} -o {out}: exit {r.returncode}, stderr {r.stderr.strip()!r}, "
                 f"input kept: {open(victim, 'rb').read() == before}")
        else:
            print(f"refine {os.path.basename(inp)} -o {os.path.basename(out)}: refused, the input kept")

    # lepp certify with a bare input prefix: the .poly's mesh certifies
    # against it; the .node's mesh (another domain) does not.
    c = run([lepp, "certify", both, os.path.join(scratch, "full-poly"), "--min-angle", "30"])
    full = run([lepp, "certify", poly_src, os.path.join(scratch, "full-poly"), "--min-angle", "30"])
    if c.returncode != 0 or c.stdout != full.stdout:
        fail(f"certify PREFIX MESH: exit {c.returncode} (full name: {full.returncode}), "
             f"same report as the full name: {c.stdout == full.stdout}: {c.stderr.strip()}")
    else:
        print("certify with a bare prefix: certified, the same report as with PREFIX.poly")
    c = run([lepp, "certify", both, os.path.join(scratch, "full-node"), "--min-angle", "30"])
    if c.returncode != 1:
        fail(f"certify PREFIX (the .poly) against the .node's mesh: expected exit 1, got {c.returncode}: {c.stderr.strip()}")

    # neither exists: exit 2, one line naming the prefix and both files
    missing = os.path.join(scratch, "missing")
    expect_missing(lepp, [lepp, "refine", missing, "-o", missing + "-out", "-q"], missing)
    expect_missing(lepp, [lepp, "certify", missing, os.path.join(scratch, "full-poly")], missing)

    print(f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
