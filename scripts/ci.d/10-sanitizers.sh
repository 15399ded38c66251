#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The test suite again under AddressSanitizer and UndefinedBehaviorSanitizer
# (gcc, LEPP_SANITIZE=ON), in build-asan/, without benchmarks or fuzz targets.
# Every registered test runs except those labelled "slow-under-asan" (none of
# the hostile-input tests or small-angle properties may carry that label).
# -O1 -g1: ASan's recommended optimisation, and line tables for readable
# reports without the compile cost of full debug info on CGAL.
set -euo pipefail
cd "$(dirname "$0")/../.."
build=build-asan
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -g1 -DNDEBUG" \
  -DLEPP_SANITIZE=ON -DLEPP_BUILD_BENCH=OFF -DLEPP_BUILD_FUZZ=OFF -DLEPP_LONG_TESTS=OFF
start=$(date +%s)
cmake --build "$build" -j "$(nproc)"
echo "sanitizer build: $(( $(date +%s) - start )) s"
export ASAN_OPTIONS="abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
start=$(date +%s)
ctest --test-dir "$build" --output-on-failure -j "$(nproc)" --timeout 900 -LE slow-under-asan
echo "sanitizer tests: $(( $(date +%s) - start )) s"
