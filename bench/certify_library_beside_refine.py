#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""lepp.certify beside lepp.refine, the library calls through Python (issue 40 item 3:
the certifier's library call as fast as the mesher's). Square400 at theta = 30 and
--max-area A, in memory: no file is read or written. Each round runs lepp.refine, then
lepp.certify of its mesh with threads=1 and threads=2; prints the medians of the
process's CPU time (user + system) of each call and certify's over refine's.

usage: bench/certify_library_beside_refine.py BUILD/python [AREA=0.015] [ROUNDS=5]
(Debian's python3, with the build's package on the path; 0.0015 is about 10^7 triangles.)
"""
import os
import resource
import statistics
import sys

sys.path.insert(0, sys.argv[1])
import lepp  # noqa: E402

area = float(sys.argv[2]) if len(sys.argv) > 2 else 0.015
rounds = int(sys.argv[3]) if len(sys.argv) > 3 else 5
poly = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "corpus", "paper", "square400.poly")


def cpu():
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime


times = {"refine": [], "certify, threads=1": [], "certify, threads=2": []}
for _ in range(rounds):
    start = cpu()
    mesh = lepp.refine(poly, min_angle=30, max_area=area)
    times["refine"].append(cpu() - start)
    for threads in (1, 2):
        start = cpu()
        report = lepp.certify(poly, mesh, min_angle=30, max_area=area, threads=threads)
        times[f"certify, threads={threads}"].append(cpu() - start)
        if not report:
            sys.exit(f"the mesh was not certified:\n{report.text}")
median = {name: statistics.median(t) for name, t in times.items()}
print(f"Square400, theta = 30, area bound {area}; CPU medians of {rounds} rounds")
for name, m in median.items():
    print(f"  lepp.{name}: {m:.3f} s")
print(f"lepp.certify over lepp.refine, one thread, CPU: {median['certify, threads=1'] / median['refine']:.2f}")
