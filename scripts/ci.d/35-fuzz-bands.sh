#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The fuzzers guard the paper's bands (issue 28, docs/FUZZING.md "In CI"): each
# target in its band, from the committed seeds, for a fixed number of executions
# with a fixed libFuzzer seed (one process: deterministic for a given commit),
# built with clang-14, libFuzzer, ASan and UBSan in build-fuzz/. A finding
# fails the job with its finding line and the input's path. fuzz_engine audits
# lepp's own traced runs (build/cli/lepp, which the test job built first).
#   LEPP_CI_FUZZ_SCALE=N multiplies every count (default 1); LEPP_CI_FUZZ_ONLY=NAME runs one row.
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$(pwd)
build=${LEPP_CI_FUZZ_BUILD:-build-fuzz}  # fuzz/run.sh's build too (same configuration)
scale=${LEPP_CI_FUZZ_SCALE:-1}
lepp=$root/build/cli/lepp
[[ -x $lepp ]] || { echo "35-fuzz-bands: $lepp is missing (scripts/build.sh first)" >&2; exit 1; }
if [[ ! -f $build/CMakeCache.txt ]]; then
  CC=clang-14 CXX=clang++-14 cmake -S . -B "$build" -G Ninja -DLEPP_BUILD_FUZZ=ON -DLEPP_BUILD_TESTS=OFF \
    -DLEPP_BUILD_BENCH=OFF >/dev/null
fi
start=$(date +%s)
ninja -C "$build" -j "$(nproc)" fuzz_parse fuzz_cdt fuzz_refine fuzz_differential fuzz_engine fuzz_audit >/dev/null
echo "fuzz build: $(( $(date +%s) - start )) s"
# The coverage instrumentation at work: no comparison hooks; edge counters in lepp's code, none in third-party code.
bash fuzz/tests/coverage_hooks.sh objdump "$build/fuzz/fuzz_refine"

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export ASAN_OPTIONS="abort_on_error=1:detect_leaks=0" UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
failed=0
source fuzz/ci_rows.sh
for row in "${fuzz_ci_rows[@]}"; do
  read -r name target runs vars <<<"$row"
  [[ -n ${LEPP_CI_FUZZ_ONLY:-} && $name != "$LEPP_CI_FUZZ_ONLY" ]] && continue
  runs=$(( runs * scale ))
  work=$tmp/$name
  mkdir -p "$work/corpus" "$work/findings" "$work/known" "$work/engine"
  seeds=$root/corpus/fuzz/$target
  [[ -d $seeds ]] || seeds=$root/corpus/fuzz/fuzz_refine
  # shellcheck disable=SC2086
  fuzz_row_env "$work" "$target" "$lepp" ${vars:-}
  dict=()
  [[ -f fuzz/$target.dict ]] && dict=(-dict="fuzz/$target.dict")
  start=$(date +%s)
  status=0
  env "${row_env[@]}" "$build/fuzz/$target" -seed=1 -runs="$runs" -timeout=300 -rss_limit_mb=4096 -malloc_limit_mb=2048 \
    "${dict[@]}" -artifact_prefix="$work/findings/" "$work/corpus" "$seeds" >"$work/log" 2>&1 || status=$?
  secs=$(( $(date +%s) - start ))
  if [[ $status -ne 0 ]]; then
    failed=1
    echo "FINDING: $name ($target, $runs runs, ${vars:-default band}) after $secs s, exit $status:"
    grep -m3 'LEPP-FINDING\|ERROR: \|SUMMARY' "$work/log" || tail -20 "$work/log"
    mkdir -p out/ci-fuzz && cp -r "$work/findings" "out/ci-fuzz/$name" && echo "  input: out/ci-fuzz/$name/"
    echo "  reproduce: fuzz/promote.sh out/ci-fuzz/$name/<file> (docs/FUZZING.md)"
  else
    echo "ok: $name ($target, $runs runs, ${vars:-default band}) in $secs s"
  fi
done
exit $failed
