#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# lepp certify beside lepp refine, in one measurement (issue 40 item 3: the checker at
# least as fast as the mesher): Square400 at theta = 30 degrees and --max-area A. Each
# round runs, in turn: lepp refine --threads 1 (writing the mesh into new files: the last
# round's are removed first, untimed), lepp certify of that
# mesh with --threads 1 and --threads 2, and, when BEFORE names another lepp binary
# (an older build), its certify with --threads 1 and 2 too. Whole processes; medians of
# wall time, CPU time (user + system) and peak resident memory (the child's rusage:
# bench/lib/interleave.py), and the least wall and CPU of the rounds (on a shared
# machine, the rounds least disturbed); prints a markdown table and certify's wall over refine's.
# Needs no Triangle (beside_triangle.sh measures the same certify ratios beside Triangle).
# usage: bench/certify_beside_refine.sh LEPP
# environment: AREA=0.015 (about 10^6 triangles; 0.0015: 10^7), RUNS=5, BEFORE=path to
#   another lepp, OUT=/tmp (the mesh, about 60 bytes a triangle), LEPP_BENCH_QUIET=1
#   (each round waits, up to 2 minutes, until the machine is 90 % idle: on a machine
#   shared with other work, rounds that start when nothing else runs).
set -euo pipefail
cd "$(dirname "$0")/.."
lepp=$(readlink -f "${1:?usage: bench/certify_beside_refine.sh LEPP}")
before=${BEFORE:+$(readlink -f "$BEFORE")}
area=${AREA:-0.015}
rounds=${RUNS:-5}
out_dir=$(mktemp -d "${OUT:-/tmp}/certify_beside_refine.XXXXXX")
trap 'rm -rf "$out_dir"' EXIT
cp corpus/paper/square400.poly "$out_dir/in.poly"

# The loop and the medians: bench/lib/interleave.py (shared with beside_triangle.sh).
PYTHONPATH=bench/lib python3 - "$lepp" "${before:-}" "$out_dir" "$area" "$rounds" <<'PY'
import sys
from interleave import Step, first_count, markdown_table, medians, minima, remove_outputs, run_rounds
lepp, before, out, area, rounds = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4], int(sys.argv[5])
inp, mesh = f"{out}/in.poly", f"{out}/mesh"

def certify(name, label, binary, threads):
    return Step(name, label, [binary, "certify", inp, mesh, "--min-angle", "30", "--max-area", area, "--threads", threads])

steps = [
    Step("refine1", "lepp refine --threads 1",
         [lepp, "refine", inp, "--min-angle", "30", "--max-area", area, "--threads", "1", "-q", "-o", mesh],
         first=remove_outputs(mesh)),  # new files each round, not the last round's truncated
    certify("certify1", "lepp certify --threads 1", lepp, 1),
    certify("certify2", "lepp certify --threads 2", lepp, 2),
]
if before:
    steps += [certify("before1", "before: lepp certify --threads 1", before, 1),
              certify("before2", "before: lepp certify --threads 2", before, 2)]
samples = run_rounds(steps, rounds, "bench/certify_beside_refine.sh")
med, least = medians(samples), minima(samples)
triangles = first_count(f"{mesh}.ele")
refine_wall = med["refine1"]["wall"]
refine_least = least["refine1"]["wall"]

print(f"Square400, theta = 30, area bound {area}, {triangles:,} triangles; medians of {rounds} interleaved rounds")
print()
print(markdown_table(steps, med, [
    ("wall s", lambda s, m: f"{m['wall']:.2f}"),
    ("CPU s", lambda s, m: f"{m['cpu']:.2f}"),
    ("peak MiB", lambda s, m: f"{m['peak'] / 2**20:,.0f}"),
    ("wall / refine's", lambda s, m: f"{m['wall'] / refine_wall:.2f}"),
    ("least wall s", lambda s, m: f"{least[s.name]['wall']:.2f}"),
    ("least CPU s", lambda s, m: f"{least[s.name]['cpu']:.2f}"),
    ("least wall / refine's least", lambda s, m: f"{least[s.name]['wall'] / refine_least:.2f}"),
]))
print()
print(f"- lepp certify over lepp refine, one thread, wall: **{med['certify1']['wall'] / refine_wall:.2f}** "
      f"(least walls: {least['certify1']['wall'] / refine_least:.2f}; issue 40: at most 1)")
print(f"- lepp certify --threads 2 over lepp refine --threads 1, wall: **{med['certify2']['wall'] / refine_wall:.2f}** "
      f"(least walls: {least['certify2']['wall'] / refine_least:.2f}; issue 40: at most 0.6)")
PY
