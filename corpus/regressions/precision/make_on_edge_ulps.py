#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes on-edge-ulps.poly (issue 28): the unit square, points along its diagonal
and its other diagonal at a few fixed fractions, and a grid of points a few ulps
apart around the diagonal's midpoint (0.5, 0.5): rows 0.5 + A ulps and 0.5 - B ulps
(the ulp is 2^-53 above 0.5 and 2^-54 below it), columns 0.5 + K ulps. The kind of
input CDT libraries test "points on an edge" with: many vertices within ulps of one
line, so lengths tie exactly and rounded midpoints fall on the line or off it.

usage: make_on_edge_ulps.py SEED OUT   (the fractions along the diagonals drawn with SEED)
on-edge-ulps.poly is: make_on_edge_ulps.py SEED on-edge-ulps.poly, SEED in its header
"""
import random, sys

def up(x, k):   # k ulps above x (x a double of [0.5, 1))
    return x + k * 2.0**-53
def down(x, k):  # k ulps below x (x in (0.25, 0.5])
    return x - k * 2.0**-54

pts = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
seed = int(sys.argv[1])
rnd = random.Random(seed)
for t in sorted(rnd.sample(range(1, 100), 10)) + [50]:
    pts.append((t / 100, t / 100))
for t in sorted(rnd.sample(range(5, 96, 5), 5)):
    pts.append((1.0 - t / 100, t / 100))
pts += [(up(0.5, 1), up(0.5, 1)), (down(0.5, 1), down(0.5, 1)), (up(0.5, 1), down(0.5, 1)), (down(0.5, 1), up(0.5, 1))]
for y in (up(0.5, 1), down(0.5, 1), down(0.5, 3)):
    for k in (2, 3, 4):
        pts.append((up(0.5, k), y))
pts.append((up(0.5, 6), down(0.5, 1)))
pts = list(dict.fromkeys(pts))
with open(sys.argv[2], 'w') as f:
    f.write(f"# {len(pts)} points: the unit square, its diagonals at fixed fractions, a grid a few ulps apart at (0.5, 0.5)\n"
            f"# (issue 28; made by make_on_edge_ulps.py {seed})\n")
    f.write(f"{len(pts)} 2 0 0\n")
    for i, (x, y) in enumerate(pts):
        f.write(f"{i + 1} {x!r} {y!r}\n")
    f.write("0 0\n0\n")
