#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The batch order against fifo (docs/PAPER.md, "The batch order against fifo").

Every paper problem, both methods, theta in 20, 25, 28, 30, 32, 34, 35, 36 degrees,
`lepp refine --order fifo` and `--order batch` (the fast engine, the default
guards): points added, outcome, smallest and average smallest angle, rounds.
Prints the markdown table and the summary lines of that section.

usage: paper/batch_vs_fifo.py LEPP [SOURCE_DIR]
"""
import json
import math
import os
import subprocess
import sys
import tempfile

PROBLEMS = ["A", "circles240", "rect162", "square400"]
ANGLES = [20, 25, 28, 30, 32, 34, 35, 36]


def run(lepp, poly, theta, method, order, out):
    r = subprocess.run([lepp, "refine", poly, "-o", out, "--min-angle", str(theta), "--method", method,
                        "--order", order, "--json", "-q"], capture_output=True, text=True)
    if r.returncode not in (0, 3):
        sys.exit(f"lepp refine {poly} --order {order}: exit {r.returncode}: {r.stderr.strip()}")
    return json.loads(r.stdout)


def main():
    lepp = sys.argv[1]
    source = sys.argv[2] if len(sys.argv) > 2 else os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    print("| problem | method | θ | fifo points | batch points | batch / fifo | fifo outcome | batch outcome "
          "| smallest angle fifo / batch | average smallest fifo / batch | rounds |")
    print("|---|---|---:|---:|---:|---:|---|---|---|---|---:|")
    ratios = {"centroid": [], "midpoint": []}
    converged = {("centroid", "fifo"): 0, ("centroid", "batch"): 0, ("midpoint", "fifo"): 0, ("midpoint", "batch"): 0}
    with tempfile.TemporaryDirectory() as tmp:
        for problem in PROBLEMS:
            poly = os.path.join(source, "corpus", "paper", problem + ".poly")
            for method in ("centroid", "midpoint"):
                for theta in ANGLES:
                    f = run(lepp, poly, theta, method, "fifo", os.path.join(tmp, "f"))
                    b = run(lepp, poly, theta, method, "batch", os.path.join(tmp, "b"))
                    both = f["outcome"] == "converged" and b["outcome"] == "converged"
                    for order, j in (("fifo", f), ("batch", b)):
                        converged[(method, order)] += j["outcome"] == "converged"
                    ratio = b["steiner_points"] / max(f["steiner_points"], 1)
                    if both and theta <= 35:
                        ratios[method].append(ratio)
                    print(f"| {problem} | {method} | {theta} | {f['steiner_points']} | {b['steiner_points']} | {ratio:.3f} "
                          f"| {f['outcome']} | {b['outcome']} | {f['min_angle']:.2f} / {b['min_angle']:.2f} "
                          f"| {f['avg_min_angle']:.2f} / {b['avg_min_angle']:.2f} | {b['rounds']} |")
    print()
    for method in ("centroid", "midpoint"):
        r = ratios[method]
        geo = math.exp(sum(math.log(x) for x in r) / len(r)) if r else float("nan")
        print(f"- {method}: converged fifo {converged[(method, 'fifo')]}, batch {converged[(method, 'batch')]} of "
              f"{len(PROBLEMS) * len(ANGLES)}; where both converge at θ ≤ 35°, batch adds {geo:.3f} times fifo's points "
              f"(geometric mean of {len(r)} runs; fewest {min(r):.3f}, most {max(r):.3f})")


if __name__ == "__main__":
    main()
