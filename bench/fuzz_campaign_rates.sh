#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# libFuzzer's own rates (issue 40, item 4): CI's fuzz rows (scripts/ci.d/35-fuzz-bands.sh:
# the same targets, bands, committed seeds, -seed=1 and run counts) in each fuzz build
# given, the builds in turn per row (the same load for both). Prints a markdown table
# per row and build: executions, CPU seconds (user + system, children included), and
# executions per CPU second and per wall second. A finding stops the row and is printed.
# usage: bench/fuzz_campaign_rates.sh FUZZ_BUILD... (each with fuzz/<target> built)
#   SCALE=N multiplies the run counts (default 1), ONLY="row ..." (rows by name),
#   LEPP=path of the lepp that fuzz_engine runs (default build/cli/lepp).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
(( $# > 0 )) || { echo "usage: bench/fuzz_campaign_rates.sh FUZZ_BUILD..." >&2; exit 2; }
scale=${SCALE:-1}
lepp=$(readlink -f "${LEPP:-build/cli/lepp}")
[[ -x $lepp ]] || { echo "fuzz_campaign_rates: $lepp is missing (fuzz_engine runs it)" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export ASAN_OPTIONS="abort_on_error=1:detect_leaks=0" UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"

source fuzz/ci_rows.sh  # CI's rows

echo "| row | build | executions | wall s | CPU s | exec/s (CPU) | exec/s (wall) |"
echo "|---|---|---:|---:|---:|---:|---:|"
failed=0
for row in "${fuzz_ci_rows[@]}"; do
  read -r name target runs vars <<<"$row"
  if [[ -n ${ONLY:-} && " $ONLY " != *" $name "* ]]; then continue; fi
  runs=$(( runs * scale ))
  seeds=$root/corpus/fuzz/$target
  [[ -d $seeds ]] || seeds=$root/corpus/fuzz/fuzz_refine
  dict=()
  [[ -f fuzz/$target.dict ]] && dict=(-dict="fuzz/$target.dict")
  for build in "$@"; do
    work=$tmp/$name-$(basename "$(dirname "$(readlink -f "$build")")")-$(basename "$build")
    rm -rf "$work" && mkdir -p "$work/corpus" "$work/findings" "$work/known" "$work/engine"
    # shellcheck disable=SC2086
    fuzz_row_env "$work" "$target" "$lepp" ${vars:-}
    start=$(date +%s.%N)
    status=0
    env "${row_env[@]}" python3 bench/lib/cpu_time.py "$work/time" "$build/fuzz/$target" -seed=1 -runs="$runs" \
      -timeout=300 -rss_limit_mb=4096 -malloc_limit_mb=2048 -print_final_stats=1 "${dict[@]}" \
      -artifact_prefix="$work/findings/" "$work/corpus" "$seeds" >"$work/log" 2>&1 || status=$?
    end=$(date +%s.%N)
    if [[ $status -ne 0 ]]; then
      failed=1
      echo "fuzz_campaign_rates: $name in $build stopped, exit $status:" >&2
      grep -m3 'LEPP-FINDING\|ERROR: \|SUMMARY' "$work/log" >&2 || tail -5 "$work/log" >&2
      continue
    fi
    execs=$(awk '/stat::number_of_executed_units/ { print $2 }' "$work/log")
    awk -v n="$name" -v b="$build" -v k="$execs" -v s="$start" -v e="$end" '
      END { c = $1 + $2; w = e - s
            printf "| %s | %s | %d | %.1f | %.1f | %.1f | %.1f |\n", n, b, k, w, c, (c > 0 ? k / c : 0), k / w }' "$work/time"
  done
done
exit $failed
