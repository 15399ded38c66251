#!/usr/bin/env bash
# The test suite again under AddressSanitizer and UndefinedBehaviorSanitizer
# (gcc), in build-asan/, without benchmarks. Everything runs except the tests
# labelled "slow-under-asan" (none of the hostile tests or small-angle
# properties are). The ASan build is RelWithDebInfo: -O2 keeps CGAL fast enough,
# debug info makes reports readable.
set -euo pipefail
cd "$(dirname "$0")/../.."
build=build-asan
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLEPP_SANITIZE=ON -DLEPP_BUILD_BENCH=OFF \
  -DLEPP_BUILD_FUZZ=OFF -DLEPP_LONG_TESTS=OFF
cmake --build "$build" -j "$(nproc)"

export ASAN_OPTIONS="abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
ctest --test-dir "$build" --output-on-failure -j "$(nproc)" --timeout 900 -LE slow-under-asan
