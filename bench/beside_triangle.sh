#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# lepp beside Triangle, in one measurement (issue 40): every ratio against Triangle is
# computed from runs of both programs made here, interleaved, never from a time of
# another day. Square400 at theta = 30 degrees and --max-area A, whole processes writing
# their files. Each round runs, in turn: lepp refine --threads 1, lepp refine --threads 2
# (fifo; the output beside the refinement), Triangle -pq30 -aA, lepp certify of lepp's
# mesh with --threads 1 and --threads 2 (when certify has the option). Medians of wall
# time, CPU time (user + system) and peak resident memory (GNU time); prints a markdown
# table and the ratios the issue asks for.
# usage: TRIANGLE=path/to/triangle bench/beside_triangle.sh LEPP
# environment: AREA=0.015 (about 10^6 triangles; 0.0015: 10^7), RUNS=5 (issue 40: at
#   least 5 pairs at 10^6, 3 at 10^7), OUT=/tmp (the meshes, about 60 bytes a triangle).
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

certify_threads=()
if "$lepp" certify --help 2>/dev/null | grep -q -- '--threads'; then certify_threads=(--threads); fi

run() {  # NAME COMMAND...: one timed run, appended to NAME's list
  local name=$1
  shift
  /usr/bin/time -f "%e %U %S %M" -o "$out_dir/time" "$@" > /dev/null 2> "$out_dir/err" \
    || { local rc=$?; [[ $rc == 3 ]] || { echo "$name failed ($rc):" >&2; cat "$out_dir/err" >&2; exit 1; }; }
  tail -1 "$out_dir/time" >> "$out_dir/$name.times"
}

names=(lepp1 lepp2 triangle certify1)
[[ ${#certify_threads[@]} -gt 0 ]] && names+=(certify2)
for ((r = 0; r < rounds; ++r)); do
  [[ -t 2 ]] && printf '\rbench/beside_triangle.sh: round %d of %d' $((r + 1)) "$rounds" >&2
  run lepp1 "$lepp" refine "$out_dir/in.poly" --min-angle 30 --max-area "$area" --threads 1 -q -o "$out_dir/lepp"
  run lepp2 "$lepp" refine "$out_dir/in.poly" --min-angle 30 --max-area "$area" --threads 2 -q -o "$out_dir/lepp"
  run triangle "$triangle" -pq30 -a"$area" -Q "$out_dir/in.poly"
  triangles_triangle=$(head -1 "$out_dir/in.1.ele" | awk '{print $1}')
  rm -f "$out_dir"/in.1.*
  run certify1 "$lepp" certify "$out_dir/in.poly" "$out_dir/lepp" --min-angle 30 --max-area "$area" \
    ${certify_threads[@]:+--threads 1}
  if [[ ${#certify_threads[@]} -gt 0 ]]; then
    run certify2 "$lepp" certify "$out_dir/in.poly" "$out_dir/lepp" --min-angle 30 --max-area "$area" --threads 2
  fi
done
[[ -t 2 ]] && printf '\r\033[K' >&2
triangles_lepp=$(head -1 "$out_dir/lepp.ele" | awk '{print $1}')

python3 - "$out_dir" "$area" "$rounds" "$triangles_lepp" "$triangles_triangle" "${names[@]}" <<'PY'
import statistics, sys
out, area, rounds, tri_lepp, tri_triangle = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4]), int(sys.argv[5])
names = sys.argv[6:]
label = {
    "lepp1": "lepp refine --threads 1", "lepp2": "lepp refine --threads 2",
    "triangle": "Triangle -pq30", "certify1": "lepp certify --threads 1", "certify2": "lepp certify --threads 2",
}
med = {}
for n in names:
    rows = [list(map(float, line.split())) for line in open(f"{out}/{n}.times")]
    med[n] = dict(wall=statistics.median(r[0] for r in rows),
                  cpu=statistics.median(r[1] + r[2] for r in rows),
                  peak=statistics.median(r[3] for r in rows) * 1024)
print(f"Square400, theta = 30, area bound {area}; medians of {rounds} interleaved rounds")
print()
print("| program | triangles | wall s | CPU s | peak MiB | peak bytes / triangle |")
print("|---|---:|---:|---:|---:|---:|")
for n in names:
    t = tri_triangle if n == "triangle" else tri_lepp
    m = med[n]
    print(f"| {label[n]} | {t:,} | {m['wall']:.2f} | {m['cpu']:.2f} | {m['peak'] / 2**20:,.0f} | {m['peak'] / t:.1f} |")
print()
tr = med["triangle"]
print(f"- Triangle's CPU over lepp's, one thread: **{tr['cpu'] / med['lepp1']['cpu']:.2f}x** (issue 40: at least 3.5)")
print(f"- Triangle's wall over lepp's, two threads: **{tr['wall'] / med['lepp2']['wall']:.2f}x** (issue 40: at least 4.5)")
print(f"- lepp certify over lepp refine, one thread, wall: **{med['certify1']['wall'] / med['lepp1']['wall']:.2f}** (issue 40: at most 1)")
if "certify2" in med:
    print(f"- lepp certify --threads 2 over lepp refine --threads 1, wall: **{med['certify2']['wall'] / med['lepp1']['wall']:.2f}** (issue 40: at most 0.6)")
PY
