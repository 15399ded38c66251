#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Fuzzing throughput (issue 40, item 4): a fixed corpus per band of CI's fuzz job
# (bench/fuzz-corpus/ROW, the rows of scripts/ci.d/35-fuzz-bands.sh with their
# environment) replayed once through each fuzz target, in two builds:
#   release:   BUILD/fuzz/<target>_replay --as-fuzzer (the default Release build, g++)
#   sanitizer: FUZZ_BUILD/fuzz/<target> FILE... (clang-14, libFuzzer, ASan, UBSan:
#              CI's fuzz build), each file run once, as libFuzzer runs a corpus.
# The checks are the fuzzers' own: a finding stops the row (the corpus is clean on
# main); known classes are kept in a scratch directory. fuzz_engine runs BUILD's
# lepp, traced, as CI does. Prints a markdown table: inputs, wall and CPU seconds
# (user + system, children included: the rate to compare on a shared machine) and
# executions per CPU second and per wall second; the median of REPEAT runs.
# usage: bench/fuzz_throughput.sh [BUILD] [FUZZ_BUILD]   (default build, build-fuzz)
#   MODES="release sanitizer" (one of them to skip the other), ONLY="row ..." (rows by name),
#   REPEAT=1, CORPUS=bench/fuzz-corpus. Run it on an idle core: nice, not under load.
#   BEFORE="OLD_BUILD OLD_FUZZ_BUILD": another tree's two builds (a worktree of the commit
#   compared with) replayed in the same run, each repetition the old then the new, and the
#   ratio of the medians printed: a ratio only against the other run of the same measurement.
set -euo pipefail
cd "$(dirname "$0")/.."
build=$(readlink -f "${1:-build}")
fuzz_build=$(readlink -f "${2:-build-fuzz}")
modes=${MODES:-release sanitizer}
repeat=${REPEAT:-1}
corpus=$(readlink -f "${CORPUS:-bench/fuzz-corpus}")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export ASAN_OPTIONS="abort_on_error=1:detect_leaks=0" UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"

source fuzz/ci_rows.sh  # CI's rows (their run counts unused: a replay runs each input once)

# One replay: prints "WALL CPU" in seconds, or fails with the log's finding lines.
replay() {  # BUILD FUZZ_BUILD MODE NAME TARGET VARS...
  local build=$1 fuzz_build=$2 mode=$3 name=$4 target=$5
  shift 5
  local work=$tmp/$mode-$name
  rm -rf "$work" && mkdir -p "$work/known" "$work/engine"
  local row_env
  fuzz_row_env "$work" "$target" "$build/cli/lepp" "$@"
  local cmd
  if [[ $mode == release ]]; then
    cmd=("$build/fuzz/${target}_replay" --as-fuzzer "$corpus/$name")
  else
    cmd=("$fuzz_build/fuzz/$target" -timeout=300 -rss_limit_mb=4096 -malloc_limit_mb=2048
         -artifact_prefix="$work/" "$corpus/$name"/*)
  fi
  local start end status=0
  start=$(date +%s.%N)
  env "${row_env[@]}" python3 bench/lib/cpu_time.py "$work/time" "${cmd[@]}" > "$work/log" 2>&1 || status=$?
  end=$(date +%s.%N)
  if [[ $status -ne 0 ]]; then
    echo "fuzz_throughput: $mode $name ($target) stopped, exit $status:" >&2
    grep -m3 'LEPP-FINDING\|ERROR: \|SUMMARY\|FAIL' "$work/log" >&2 || tail -5 "$work/log" >&2
    return 1
  fi
  awk -v s="$start" -v e="$end" 'END { printf "%.3f %.3f\n", e - s, $1 + $2 }' "$work/time"
}

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

before=()
if [[ -n ${BEFORE:-} ]]; then
  read -r -a before <<<"$BEFORE"
  [[ ${#before[@]} -eq 2 ]] || { echo "fuzz_throughput: BEFORE takes two paths, OLD_BUILD OLD_FUZZ_BUILD" >&2; exit 2; }
  before=("$(readlink -f "${before[0]}")" "$(readlink -f "${before[1]}")")
fi
# The trees measured: the new one, and the old one first when BEFORE is set.
trees=("$build $fuzz_build")
[[ ${#before[@]} -eq 2 ]] && trees=("${before[0]} ${before[1]}" "$build $fuzz_build")

for tree in "${trees[@]}"; do
  read -r b f <<<"$tree"
  for mode in $modes; do
    case $mode in
      release) probe=$b/fuzz/fuzz_parse_replay ;;
      sanitizer) probe=$f/fuzz/fuzz_parse ;;
      *) echo "fuzz_throughput: unknown mode $mode (release, sanitizer)" >&2; exit 2 ;;
    esac
    [[ -x $probe ]] || { echo "fuzz_throughput: $probe is missing (build the fuzz targets of $mode first)" >&2; exit 2; }
  done
  [[ -x $b/cli/lepp ]] || { echo "fuzz_throughput: $b/cli/lepp is missing (fuzz_engine runs it)" >&2; exit 2; }
done

# The CPU and wall medians of a times file: "CPU WALL", unrounded (the ratio is taken of them).
medians() { echo "$(cut -d' ' -f2 "$1" | median) $(cut -d' ' -f1 "$1" | median)"; }

if [[ ${#before[@]} -eq 2 ]]; then
  echo "| row | build | inputs | before CPU s | CPU s | before exec/s (CPU) | exec/s (CPU) | x before |"
  echo "|---|---|---:|---:|---:|---:|---:|---:|"
else
  echo "| row | build | inputs | wall s | CPU s | exec/s (CPU) | exec/s (wall) |"
  echo "|---|---|---:|---:|---:|---:|---:|"
fi
failed=0
for row in "${fuzz_ci_rows[@]}"; do
  read -r name target _runs vars <<<"$row"
  if [[ -n ${ONLY:-} && " $ONLY " != *" $name "* ]]; then continue; fi
  [[ -d $corpus/$name ]] || { echo "fuzz_throughput: $corpus/$name is missing" >&2; exit 2; }
  inputs=$(find "$corpus/$name" -maxdepth 1 -type f | wc -l)
  for mode in $modes; do
    : > "$tmp/times"
    : > "$tmp/times-before"
    for ((i = 0; i < repeat; ++i)); do
      if [[ ${#before[@]} -eq 2 ]]; then
        # shellcheck disable=SC2086
        if ! replay "${before[0]}" "${before[1]}" "$mode" "$name" "$target" $vars >> "$tmp/times-before"; then
          failed=1; continue 2
        fi
      fi
      # shellcheck disable=SC2086
      if ! replay "$build" "$fuzz_build" "$mode" "$name" "$target" $vars >> "$tmp/times"; then failed=1; continue 2; fi
    done
    read -r cpu wall <<<"$(medians "$tmp/times")"
    if [[ ${#before[@]} -eq 2 ]]; then
      read -r old_cpu _ <<<"$(medians "$tmp/times-before")"
      awk -v n="$name" -v m="$mode" -v k="$inputs" -v oc="$old_cpu" -v c="$cpu" \
        'BEGIN { printf "| %s | %s | %d | %.2f | %.2f | %.1f | %.1f | %.2f |\n", n, m, k, oc, c,
                 (oc > 0 ? k / oc : 0), (c > 0 ? k / c : 0), (c > 0 ? oc / c : 0) }'
    else
      awk -v n="$name" -v m="$mode" -v k="$inputs" -v w="$wall" -v c="$cpu" \
        'BEGIN { printf "| %s | %s | %d | %.2f | %.2f | %.1f | %.1f |\n", n, m, k, w, c, (c > 0 ? k / c : 0), k / w }'
    fi
  done
done
exit $failed
