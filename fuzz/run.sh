#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the fuzz targets with clang-14 (libFuzzer, ASan, UBSan) and runs one.
#   fuzz/run.sh TARGET SECONDS [JOBS]     (SECONDS "build": build the target, run nothing)
# The corpus grows in $LEPP_FUZZ_WORK/TARGET/corpus (default out/fuzz), seeded
# from corpus/fuzz/TARGET; crashes, loops and mismatches land in
# $LEPP_FUZZ_WORK/TARGET/findings; one example of each known loop class and
# theta band (outside the paper's claims; the run goes on) in
# $LEPP_FUZZ_WORK/TARGET/findings/known (LEPP_FUZZ_KNOWN_DIR). JOBS > 1 uses
# libFuzzer's -fork mode. fuzz_engine needs LEPP_ENGINE_CMD (docs/FUZZING.md)
# and starts from fuzz_refine's seeds.
# Extra libFuzzer flags: LEPP_FUZZ_FLAGS. The target's own environment
# (LEPP_FUZZ_METHOD, LEPP_FUZZ_THETA, LEPP_FUZZ_MIN_INPUT_ANGLE, LEPP_FUZZ_IGNORE,
# LEPP_ENGINE_CMD, LEPP_ENGINE_TIMEOUT, ...)
# passes through. The last lines of the log give executions, exec/s and cov:.
set -euo pipefail
if [[ $# -lt 2 ]]; then
  echo "usage: fuzz/run.sh TARGET SECONDS [JOBS]" >&2
  exit 2
fi
target=$1 seconds=$2 jobs=${3:-1}
root=$(cd "$(dirname "$0")/.." && pwd)
build=${LEPP_FUZZ_BUILD:-$root/build-fuzz}
work=${LEPP_FUZZ_WORK:-$root/out/fuzz}/$target

if [[ ! -f $build/CMakeCache.txt ]]; then
  CC=clang-14 CXX=clang++-14 cmake -S "$root" -B "$build" -G Ninja -DLEPP_BUILD_FUZZ=ON \
    -DLEPP_BUILD_TESTS=OFF -DLEPP_BUILD_BENCH=OFF >/dev/null
fi
# LEPP_FUZZ_NO_BUILD=1 runs the binary as built (several runs at once must not race one ninja).
[[ ${LEPP_FUZZ_NO_BUILD:-0} == 1 ]] || ninja -C "$build" -j"${LEPP_BUILD_JOBS:-2}" "$target" >/dev/null
[[ $seconds == build ]] && exit 0  # fuzz/run.sh TARGET build: build only (fuzz/campaign.sh --build)

mkdir -p "$work/corpus" "$work/findings"
export LEPP_FUZZ_KNOWN_DIR=${LEPP_FUZZ_KNOWN_DIR:-$work/findings/known}
seeds=$root/corpus/fuzz/$target
[[ -d $seeds ]] || seeds=$root/corpus/fuzz/fuzz_refine  # fuzz_engine: the same structured input
flags=(-max_total_time="$seconds" -timeout=60 -rss_limit_mb=4096 -malloc_limit_mb=1024
       -artifact_prefix="$work/findings/" -print_final_stats=1)
[[ -f $root/fuzz/$target.dict ]] && flags+=(-dict="$root/fuzz/$target.dict")
if [[ $jobs -gt 1 ]]; then
  flags+=(-fork="$jobs" -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
fi
cd "$work"
status=0
TIMEFORMAT='cpu: real %R s, user %U s, sys %S s'  # CPU time of the run, for the findings table
# shellcheck disable=SC2086
time "$build/fuzz/$target" "${flags[@]}" ${LEPP_FUZZ_FLAGS:-} "$work/corpus" "$seeds" || status=$?
exit $status
