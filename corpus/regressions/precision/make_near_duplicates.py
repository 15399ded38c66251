#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes neardup30k.node (issue 20): points on a wavy ring near (5e5, 7e6), a
fraction FRAC of them with a near-duplicate at relative distance 10^LO..10^HI
in a random direction (as Triangle's greenland.node has nearly coincident points).

usage: make_near_duplicates.py SEED N FRAC LO HI OUT
neardup30k.node is: make_near_duplicates.py 20 30000 0.01 -16 -12 neardup30k.node
"""
import math, random, sys
seed=int(sys.argv[1]); n=int(sys.argv[2]); frac=float(sys.argv[3]); lo=float(sys.argv[4]); hi=float(sys.argv[5]); out=sys.argv[6]
rnd = random.Random(seed)
P = []
while len(P) < n:
    t = rnd.random()*2*math.pi
    r = 1.0 + 0.3*math.sin(7*t) + 0.05*rnd.random()
    x = 500000.0 + 100000.0*r*math.cos(t); y = 7000000.0 + 100000.0*r*math.sin(t)
    P.append((x,y))
    if rnd.random() < frac:
        rel = 10**rnd.uniform(lo,hi)
        a = rnd.random()*2*math.pi
        s = max(abs(x),abs(y))*rel
        P.append((x + s*math.cos(a), y + s*math.sin(a)))
P = list(dict.fromkeys(P))
with open(out,'w') as f:
    f.write(f"# {len(P)} points on a ring near (5e5, 7e6), {frac:g} of them with a near-duplicate at relative distance 1e{lo:g}..1e{hi:g}\n# (issue 20: like Triangle's greenland.node; made by make_near_duplicates.py {seed} {n} {frac} {lo} {hi})\n{len(P)} 2 0 0\n")
    for i,(x,y) in enumerate(P): f.write(f"{i+1} {x!r} {y!r}\n")
