#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Whole `lepp refine` processes on one core, two or more binaries side by side (issue 31):
# Square400 at theta = 30 degrees and --max-area A (0.015: about 10^6 triangles), writing
# Triangle's three files. Each binary once under callgrind (instructions: repeatable on a
# shared machine; with the share of the statistics and of the writers), then RUNS rounds
# in which every binary runs once, in turn (interleaved, so a change in the machine's
# load falls on all alike): medians of wall time, CPU time (user + system), system time
# and peak resident memory (also per output triangle). Prints a markdown table.
# usage: bench/one_core.sh LEPP... (environment: AREA=0.015 RUNS=7 CALLGRIND=1 OUT=/tmp)
set -euo pipefail
cd "$(dirname "$0")/.."
area=${AREA:-0.015}
runs=${RUNS:-7}
out_dir=$(mktemp -d "${OUT:-/tmp}/one_core.XXXXXX")
trap 'rm -rf "$out_dir"' EXIT
bins=()
for b in "$@"; do bins+=("$(readlink -f "$b")"); done
args=(refine corpus/paper/square400.poly --min-angle 30 --max-area "$area" -q)

# Instructions of the whole process and of the two parts issue 31 is about.
instructions() {  # REPORT FUNCTION: the inclusive count of the first line naming it
  grep -m1 -F "$2" <<< "$1" | awk '{gsub(",", "", $1); print $1}'
}
if [[ ${CALLGRIND:-1} == 1 ]]; then
  for i in "${!bins[@]}"; do
    valgrind --tool=callgrind --callgrind-out-file="$out_dir/cg.$i" "${bins[$i]}" "${args[@]}" -o "$out_dir/m" \
      > /dev/null 2> /dev/null
    report=$(callgrind_annotate --inclusive=yes "$out_dir/cg.$i" 2> /dev/null)
    echo "$(instructions "$report" 'PROGRAM TOTALS') $(instructions "$report" 'lepp::mesh_stats(')" \
      "$(instructions "$report" 'lepp::write_refined_mesh(')" > "$out_dir/instr.$i"
  done
fi

# Interleaved timed runs: wall, user + system, peak resident set (GNU time).
for ((r = 0; r < runs; ++r)); do
  for i in "${!bins[@]}"; do
    /usr/bin/time -f "%e %U %S %M" -o "$out_dir/time.$i.$r" "${bins[$i]}" "${args[@]}" -o "$out_dir/m" > "$out_dir/stdout.$i"
  done
done

python3 - "$out_dir" "$runs" "$area" "${bins[@]}" <<'PY'
import os, statistics, sys
out, runs, area, bins = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4:]
def millions(n):
    return f"{int(n) / 1e6:,.0f} M"
print(f"Square400, theta = 30, --max-area {area}; medians of {runs} interleaved runs, one core each")
print()
print("| binary | triangles | instructions | of which statistics | of which writing | wall s | CPU s | of which system | peak MiB | peak bytes / triangle |")
print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
for i, b in enumerate(bins):
    rows = [open(f"{out}/time.{i}.{r}").read().split()[-4:] for r in range(runs)]
    wall = statistics.median(float(x[0]) for x in rows)
    cpu = statistics.median(float(x[1]) + float(x[2]) for x in rows)
    system = statistics.median(float(x[2]) for x in rows)
    peak_kib = statistics.median(int(x[3]) for x in rows)
    triangles = next(int(l.split()[1]) for l in open(f"{out}/stdout.{i}") if l.startswith("triangles "))
    counts = open(f"{out}/instr.{i}").read().split() if os.path.exists(f"{out}/instr.{i}") else ["0"] * 3
    total, stats, writing = (millions(c) if c != "0" else "" for c in counts)
    print(f"| {b} | {triangles:,} | {total} | {stats} | {writing} | {wall:.3f} | {cpu:.3f} | {system:.3f} | "
          f"{peak_kib / 1024:.0f} | {peak_kib * 1024 / triangles:.1f} |")
PY
