#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Where a whole `lepp refine` process spends its time (issue 31): Square400 at
# theta = 30 degrees and --max-area A, writing Triangle's three files, for each
# order/threads pair asked. Each run once per round, RUNS rounds interleaved (a change
# in the machine's load falls on all alike); medians of the phases of --json's
# seconds_by_phase (read, cdt, refine, write, statistics), the process's wall, user
# and system time and peak resident memory (GNU time). Prints a markdown table.
# usage: bench/phases.sh LEPP [ORDER:THREADS ...]   (default: fifo:1 batch:1 batch:2)
# environment: AREA=0.015 (about 10^6 triangles; 0.0015: 10^7; 0.00015: 10^8),
#   RUNS=3, OUT=/tmp (the meshes: about 60 bytes a triangle on disk),
#   BEFORE=OLD_LEPP: each pair run by OLD_LEPP too, in turn with LEPP in every round
#   (a row "before" each)
set -euo pipefail
cd "$(dirname "$0")/.."
lepp=$(readlink -f "$1")
shift
binaries=("$lepp")
[[ -n ${BEFORE:-} ]] && binaries=("$(readlink -f "$BEFORE")" "$lepp")
runs_wanted=("$@")
[[ ${#runs_wanted[@]} -gt 0 ]] || runs_wanted=(fifo:1 batch:1 batch:2)
area=${AREA:-0.015}
rounds=${RUNS:-3}
out_dir=$(mktemp -d "${OUT:-/tmp}/phases.XXXXXX")
trap 'rm -rf "$out_dir"' EXIT

for ((r = 0; r < rounds; ++r)); do
  for i in "${!runs_wanted[@]}"; do
    IFS=: read -r order threads <<< "${runs_wanted[$i]}"
    for b in "${!binaries[@]}"; do
      [[ -t 2 ]] && printf '\rbench/phases.sh: round %d of %d, %s' $((r + 1)) "$rounds" "${runs_wanted[$i]}" >&2
      /usr/bin/time -f "%e %U %S %M" -o "$out_dir/time.$i.$b.$r" "${binaries[$b]}" refine corpus/paper/square400.poly \
        --min-angle 30 --max-area "$area" --order "$order" --threads "$threads" --json -q -o "$out_dir/m" \
        > "$out_dir/json.$i.$b.$r"
      rm -f "$out_dir"/m.*
    done
  done
done
[[ -t 2 ]] && printf '\r\033[K' >&2

python3 - "$out_dir" "$rounds" "$area" "${#binaries[@]}" "${runs_wanted[@]}" <<'PY'
import json, statistics, sys
out, rounds, area, nbin, wanted = sys.argv[1], int(sys.argv[2]), sys.argv[3], int(sys.argv[4]), sys.argv[5:]
phases = ["read", "cdt", "refine", "write", "statistics"]
print(f"Square400, theta = 30, --max-area {area}; medians of {rounds} interleaved runs")
print()
print("| order | threads | triangles | " + " | ".join(f"{p} s" for p in phases)
      + " | wall s | user s | system s | peak MiB | peak bytes / triangle | Steiner points / s of refine |")
print("|---|---:|---:|" + "---:|" * len(phases) + "---:|---:|---:|---:|---:|---:|")
for i, w in enumerate(wanted):
  for b in range(nbin):
    order, threads = w.split(":")
    if nbin == 2 and b == 0:
        order = "before: " + order
    runs = [json.load(open(f"{out}/json.{i}.{b}.{r}")) for r in range(rounds)]
    times = [open(f"{out}/time.{i}.{b}.{r}").read().split()[-4:] for r in range(rounds)]
    med = lambda xs: statistics.median(xs)
    triangles = runs[0]["triangles"]
    cells = [f"{med(j['seconds_by_phase'][p] for j in runs):.3f}" for p in phases]
    wall = med(float(t[0]) for t in times)
    user = med(float(t[1]) for t in times)
    system = med(float(t[2]) for t in times)
    peak = med(int(t[3]) for t in times) * 1024
    rate = med(j["steiner_points"] / j["seconds_by_phase"]["refine"] for j in runs)
    print(f"| {order} | {threads} | {triangles:,} | " + " | ".join(cells)
          + f" | {wall:.3f} | {user:.2f} | {system:.2f} | {peak / 2**20:,.0f} | {peak / triangles:.1f} | {rate / 1e6:.2f} M |")
PY
