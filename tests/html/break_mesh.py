#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""A mesh made wrong in several ways for the HTML reports' checks (issue 41): a
Steiner vertex moved by DX and the last triangle dropped (a gap in the domain:
boundary edges inside it, the Euler characteristic off; with a theta above the
mesh's, triangles below it too).  usage: break_mesh.py IN_PREFIX OUT_PREFIX [DX]"""
import shutil
import sys


def body(path):
    return [l for l in open(path).read().splitlines() if l.strip() and not l.lstrip().startswith("#")]


src, dst = sys.argv[1:3]
dx = float(sys.argv[3]) if len(sys.argv) > 3 else 0.004
node = body(src + ".node")
n = int(node[0].split()[0])
f = node[n - 2].split()  # a Steiner vertex (lepp writes them after the input's)
f[1] = repr(float(f[1]) + dx)
node[n - 2] = " ".join(f)
open(dst + ".node", "w").write("\n".join(node) + "\n")
ele = body(src + ".ele")
head = ele[0].split()
head[0] = str(int(head[0]) - 1)
open(dst + ".ele", "w").write("\n".join([" ".join(head)] + ele[1:-1]) + "\n")
shutil.copy(src + ".poly", dst + ".poly")
