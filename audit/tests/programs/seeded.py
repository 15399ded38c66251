#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Fake mesher whose output depends on a seed from its environment: runs lepp refine,
# then adds one vertex in no triangle (a certificate failure every time) at a place
# drawn from LEPP_FLAKY_SEED, or from a fresh random seed when it is not set (then
# two runs on the same input differ). usage: seeded.py LEPP IN OUT THETA
import os
import random
import subprocess
import sys

lepp, inp, out, theta = sys.argv[1:5]
subprocess.run([lepp, "refine", inp, "-o", out, "--min-angle", theta, "-q"], check=False)
seed = os.environ.get("LEPP_FLAKY_SEED")
rng = random.Random(int(seed) if seed else None)
with open(out + ".node") as f:
    lines = [l for l in f.read().splitlines() if l.strip() and not l.lstrip().startswith("#")]
head = lines[0].split()
n = int(head[0])
first = int(lines[1].split()[0])
head[0] = str(n + 1)
x = 1e6 + rng.random()
lines[0] = " ".join(head)
extra = (int(head[2]) if len(head) > 2 else 0) + (1 if len(head) > 3 and int(head[3]) else 0)
lines.append(f"{n + first} {x!r} 1000000.0" + " 0" * extra)
with open(out + ".node", "w") as f:
    f.write("\n".join(lines) + "\n")
