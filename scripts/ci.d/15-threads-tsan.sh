#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The threads under ThreadSanitizer (gcc, -fsanitize=thread), in build-tsan/: only
# the tests that run them, so the step stays small: the batch order's parallel
# selection (the same run for 1, 2, 3 and 8 threads, docs/ALGORITHM.md section 7),
# the output's canonical order split on two threads, the engine's pages populated beside it,
# lepp refine's output on two threads (the statistics beside the writing, the
# .node beside the .ele), and lepp certify's threads (the mesh's files read at once,
# the passes in ranges, the statistics beside them).
# The AddressSanitizer build (10-sanitizers.sh) runs everything else.
set -euo pipefail
cd "$(dirname "$0")/../.."
build=build-tsan
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -g1 -DNDEBUG" \
  -DCMAKE_CXX_FLAGS="-fsanitize=thread -fno-omit-frame-pointer" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" \
  -DLEPP_BUILD_BENCH=OFF -DLEPP_BUILD_FUZZ=OFF -DLEPP_LONG_TESTS=OFF >/dev/null
start=$(date +%s)
cmake --build "$build" -j "$(nproc)" --target impl_batch_threads_tests impl_memory_tests engine_refine_files_tests core_tests certify_tests
echo "thread sanitizer build: $(( $(date +%s) - start )) s"
start=$(date +%s)
# Square400, the near-duplicate points and the generated PSLGs; the other paper
# problems run the same code and cost a minute more under the sanitizer.
TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1" "$build/impl/tests/impl_batch_threads_tests" \
  --gtest_filter='-*rect162*:*circles240*:*A_midpoint*'
TSAN_OPTIONS="halt_on_error=1" "$build/impl/tests/impl_memory_tests"
TSAN_OPTIONS="halt_on_error=1" "$build/engines/tests/engine_refine_files_tests"
TSAN_OPTIONS="halt_on_error=1" "$build/core/tests/core_tests" --gtest_filter='MeshIo.TwoThreads*:MeshReadThreads.*:NodeTextStream.*:MeshStatistics.Threads*'
TSAN_OPTIONS="halt_on_error=1" "$build/properties/tests/certify_tests" --gtest_filter='CertifyThreads.*'
echo "thread sanitizer tests: $(( $(date +%s) - start )) s"
