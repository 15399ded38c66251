#!/bin/bash -eu
# SPDX-License-Identifier: GPL-3.0-or-later
# ClusterFuzzLite / OSS-Fuzz build: the project's own CMake with the
# infrastructure's $CC, $CXX, $CXXFLAGS (sanitizers, coverage) and
# $LIB_FUZZING_ENGINE; the targets and <target>_seed_corpus.zip go to $OUT.
# Run by hand (scripts/ci.d/30-fuzz-build.sh): set CC CXX CXXFLAGS LIB_FUZZING_ENGINE OUT;
# LEPP_FUZZ_TARGETS picks a subset.
if [[ -n ${SRC:-} && -d $SRC/lepp ]]; then src=$SRC/lepp; else src=$(cd "$(dirname "$0")/.." && pwd); fi
build=${WORK:-/tmp}/lepp-build-fuzz

cmake -S "$src" -B "$build" -G Ninja \
  -DCMAKE_C_COMPILER="$CC" -DCMAKE_CXX_COMPILER="$CXX" -DCMAKE_CXX_FLAGS="$CXXFLAGS" \
  -DLEPP_BUILD_FUZZ=ON -DLEPP_BUILD_TESTS=OFF -DLEPP_BUILD_BENCH=OFF \
  -DLEPP_FUZZ_INSTRUMENT="" -DLEPP_FUZZ_ENGINE="$LIB_FUZZING_ENGINE"
targets=${LEPP_FUZZ_TARGETS:-fuzz_parse fuzz_refine fuzz_differential fuzz_cdt}
# shellcheck disable=SC2086
ninja -C "$build" -j"${LEPP_BUILD_JOBS:-$(nproc)}" $targets

for target in $targets; do
  cp "$build/fuzz/$target" "$OUT/"
  (cd "$src/corpus/fuzz/$target" && zip -q -r "$OUT/${target}_seed_corpus.zip" .)
  [[ -f $src/fuzz/$target.dict ]] && cp "$src/fuzz/$target.dict" "$OUT/$target.dict"
done
