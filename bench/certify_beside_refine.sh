#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# lepp certify beside lepp refine, in one measurement (issue 40 item 3: the checker at
# least as fast as the mesher): Square400 at theta = 30 degrees and --max-area A. Each
# round runs, in turn: lepp refine --threads 1 (writing the mesh), lepp certify of that
# mesh with --threads 1 and --threads 2, and, when BEFORE names another lepp binary
# (an older build), its certify with --threads 1 and 2 too. Whole processes; medians of
# wall time, CPU time (user + system) and peak resident memory (GNU time); prints a
# markdown table and certify's wall over refine's. Needs no Triangle (beside_triangle.sh
# measures the same certify ratios beside Triangle).
# usage: bench/certify_beside_refine.sh LEPP
# environment: AREA=0.015 (about 10^6 triangles; 0.0015: 10^7), RUNS=5, BEFORE=path to
#   another lepp, OUT=/tmp (the mesh, about 60 bytes a triangle).
set -euo pipefail
cd "$(dirname "$0")/.."
lepp=$(readlink -f "${1:?usage: bench/certify_beside_refine.sh LEPP}")
before=${BEFORE:+$(readlink -f "$BEFORE")}
area=${AREA:-0.015}
rounds=${RUNS:-5}
out_dir=$(mktemp -d "${OUT:-/tmp}/certify_beside_refine.XXXXXX")
trap 'rm -rf "$out_dir"' EXIT
cp corpus/paper/square400.poly "$out_dir/in.poly"

run() {  # NAME COMMAND...: one timed run, appended to NAME's list
  local name=$1
  shift
  /usr/bin/time -f "%e %U %S %M" -o "$out_dir/time" "$@" > /dev/null 2> "$out_dir/err" \
    || { echo "$name failed:" >&2; cat "$out_dir/err" >&2; exit 1; }
  tail -1 "$out_dir/time" >> "$out_dir/$name.times"
}

names=(refine1 certify1 certify2)
[[ -n $before ]] && names+=(before1 before2)
certify() {  # NAME LEPP THREADS
  run "$1" "$2" certify "$out_dir/in.poly" "$out_dir/mesh" --min-angle 30 --max-area "$area" --threads "$3"
}
for ((r = 0; r < rounds; ++r)); do
  [[ -t 2 ]] && printf '\rbench/certify_beside_refine.sh: round %d of %d' $((r + 1)) "$rounds" >&2
  run refine1 "$lepp" refine "$out_dir/in.poly" --min-angle 30 --max-area "$area" --threads 1 -q -o "$out_dir/mesh"
  certify certify1 "$lepp" 1
  certify certify2 "$lepp" 2
  if [[ -n $before ]]; then
    certify before1 "$before" 1
    certify before2 "$before" 2
  fi
done
[[ -t 2 ]] && printf '\r\033[K' >&2
triangles=$(head -1 "$out_dir/mesh.ele" | awk '{print $1}')

python3 - "$out_dir" "$area" "$rounds" "$triangles" "${names[@]}" <<'PY'
import statistics, sys
out, area, rounds, triangles = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
names = sys.argv[5:]
label = {"refine1": "lepp refine --threads 1", "certify1": "lepp certify --threads 1", "certify2": "lepp certify --threads 2",
         "before1": "before: lepp certify --threads 1", "before2": "before: lepp certify --threads 2"}
med = {}
for n in names:
    rows = [list(map(float, line.split())) for line in open(f"{out}/{n}.times")]
    med[n] = dict(wall=statistics.median(r[0] for r in rows), cpu=statistics.median(r[1] + r[2] for r in rows),
                  peak=statistics.median(r[3] for r in rows) * 1024)
print(f"Square400, theta = 30, area bound {area}, {triangles:,} triangles; medians of {rounds} interleaved rounds")
print()
print("| program | wall s | CPU s | peak MiB | wall / refine's |")
print("|---|---:|---:|---:|---:|")
for n in names:
    m = med[n]
    print(f"| {label[n]} | {m['wall']:.2f} | {m['cpu']:.2f} | {m['peak'] / 2**20:,.0f} | {m['wall'] / med['refine1']['wall']:.2f} |")
print()
print(f"- lepp certify over lepp refine, one thread, wall: **{med['certify1']['wall'] / med['refine1']['wall']:.2f}** (issue 40: at most 1)")
print(f"- lepp certify --threads 2 over lepp refine --threads 1, wall: **{med['certify2']['wall'] / med['refine1']['wall']:.2f}** (issue 40: at most 0.6)")
PY
