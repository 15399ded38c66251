#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# lepp beside Triangle, in one measurement (issue 40): every ratio against Triangle is
# computed from runs of both programs made here, interleaved, never from a time of
# another day. Square400 at theta = 30 degrees and --max-area A, whole processes writing
# their files, each into new files (the last round's removed first, untimed, for every
# program alike). Each round runs, in turn: lepp refine --threads 1, lepp refine --threads 2
# (fifo; the output beside the refinement), Triangle -pq30 -aA, lepp certify of lepp's
# mesh with --threads 1 and --threads 2 (when certify has the option). Medians of wall
# time, CPU time (user + system) and peak resident memory (the child's rusage:
# bench/lib/interleave.py); prints a markdown table and the ratios the issue asks for.
# usage: TRIANGLE=path/to/triangle bench/beside_triangle.sh LEPP
# environment: AREA=0.015 (about 10^6 triangles; 0.0015: 10^7), RUNS=5 (issue 40: at
#   least 5 pairs at 10^6, 3 at 10^7), OUT=/tmp (the meshes, about 60 bytes a triangle),
#   BEFORE=path to another lepp (an older build): its refine --threads 1 runs in each
#   round too, after lepp's, and its ratio to Triangle is printed beside lepp's;
#   CERTIFY=0 leaves out the certify runs (the mesher's ratios alone, item 2).
# Triangle is never part of lepp: build it for benchmarks only (docs/BENCHMARKS.md).
set -euo pipefail
cd "$(dirname "$0")/.."
lepp=$(readlink -f "${1:?usage: TRIANGLE=path bench/beside_triangle.sh LEPP}")
if [[ -z ${TRIANGLE:-} || ! -x ${TRIANGLE:-} ]]; then
  echo "bench/beside_triangle.sh: skipped: set TRIANGLE to a native Triangle binary (docs/BENCHMARKS.md says how to build one)" >&2
  exit 0
fi
triangle=$(readlink -f "$TRIANGLE")
area=${AREA:-0.015}
rounds=${RUNS:-5}
out_dir=$(mktemp -d "${OUT:-/tmp}/beside_triangle.XXXXXX")
trap 'rm -rf "$out_dir"' EXIT
cp corpus/paper/square400.poly "$out_dir/in.poly"

certify_threads=0  # 1: certify has --threads (both counts run); none: no certify runs
if [[ ${CERTIFY:-1} == 0 ]]; then
  certify_threads=none
elif "$lepp" certify --help 2>/dev/null | grep -q -- '--threads'; then
  certify_threads=1
fi

# The loop and the medians: bench/lib/interleave.py (shared with certify_beside_refine.sh).
before=${BEFORE:+$(readlink -f "$BEFORE")}
PYTHONPATH=bench/lib python3 - "$lepp" "$triangle" "$out_dir" "$area" "$rounds" "$certify_threads" "${before:-}" <<'PY'
import os, sys
from interleave import Step, first_count, markdown_table, medians, remove_outputs, run_rounds
lepp, triangle, out, area, rounds, certify_threads = sys.argv[1:4] + [sys.argv[4], int(sys.argv[5]), {"1": True, "0": False}.get(sys.argv[6], "none")]
before = sys.argv[7]
inp, mesh = f"{out}/in.poly", f"{out}/lepp"
refine = [lepp, "refine", inp, "--min-angle", "30", "--max-area", area]
certify = [lepp, "certify", inp, mesh, "--min-angle", "30", "--max-area", area]
triangles = {}

def triangle_done():  # Triangle's count read, its files removed (the next round writes them again)
    triangles["triangle"] = first_count(f"{out}/in.1.ele")
    for ext in ("node", "ele", "poly"):
        os.remove(f"{out}/in.1.{ext}")

steps = [
    # Each lepp refine writes new files, as Triangle does (its files are removed after
    # each run): truncating the previous round's 48 MB cost about 0.01 s of system time.
    Step("lepp1", "lepp refine --threads 1", refine + ["--threads", "1", "-q", "-o", mesh], ok=(0, 3),
         first=remove_outputs(mesh)),
]
if before:  # its mesh written apart: certify reads lepp's
    steps.append(Step("before1", "before: lepp refine --threads 1",
                      [before] + refine[1:] + ["--threads", "1", "-q", "-o", f"{out}/before"], ok=(0, 3),
                      first=remove_outputs(f"{out}/before")))
steps += [
    Step("lepp2", "lepp refine --threads 2", refine + ["--threads", "2", "-q", "-o", mesh], ok=(0, 3),
         first=remove_outputs(mesh)),
    Step("triangle", "Triangle -pq30", [triangle, "-pq30", f"-a{area}", "-Q", inp], then=triangle_done),
]
if certify_threads != "none":
    steps.append(Step("certify1", "lepp certify --threads 1", certify + (["--threads", "1"] if certify_threads else []), ok=(0, 3)))
if certify_threads is True:
    steps.append(Step("certify2", "lepp certify --threads 2", certify + ["--threads", "2"], ok=(0, 3)))
med = medians(run_rounds(steps, rounds, "bench/beside_triangle.sh"))
lepp_triangles = first_count(f"{mesh}.ele")
count = lambda s: triangles["triangle"] if s.name == "triangle" else first_count(f"{out}/before.ele") if s.name == "before1" else lepp_triangles

print(f"Square400, theta = 30, area bound {area}; medians of {rounds} interleaved rounds")
print()
print(markdown_table(steps, med, [
    ("triangles", lambda s, m: f"{count(s):,}"),
    ("wall s", lambda s, m: f"{m['wall']:.2f}"),
    ("CPU s", lambda s, m: f"{m['cpu']:.2f}"),
    ("peak MiB", lambda s, m: f"{m['peak'] / 2**20:,.0f}"),
    ("peak bytes / triangle", lambda s, m: f"{m['peak'] / count(s):.1f}"),
]))
print()
tr = med["triangle"]
print(f"- Triangle's CPU over lepp's, one thread: **{tr['cpu'] / med['lepp1']['cpu']:.2f}x** (issue 40: at least 3.5)")
if before:
    print(f"- Triangle's CPU over the BEFORE build's, one thread: **{tr['cpu'] / med['before1']['cpu']:.2f}x**")
print(f"- Triangle's wall over lepp's, two threads: **{tr['wall'] / med['lepp2']['wall']:.2f}x** (issue 40: at least 4.5)")
if "certify1" in med:
    print(f"- lepp certify over lepp refine, one thread, wall: **{med['certify1']['wall'] / med['lepp1']['wall']:.2f}** (issue 40: at most 1)")
if "certify2" in med:
    print(f"- lepp certify --threads 2 over lepp refine --threads 1, wall: **{med['certify2']['wall'] / med['lepp1']['wall']:.2f}** (issue 40: at most 0.6)")
PY
