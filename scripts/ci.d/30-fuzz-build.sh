#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Checks that the ClusterFuzzLite build.sh works outside Docker, with the
# variables the infrastructure would set, and that its output runs.
# Only fuzz_parse (core only, quick); LEPP_FUZZ_TARGETS="..." for more.
set -euo pipefail
cd "$(dirname "$0")/../.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export CC=clang-14 CXX=clang++-14 OUT=$tmp/out WORK=$tmp/work LIB_FUZZING_ENGINE=-fsanitize=fuzzer
export CXXFLAGS="-O1 -fno-omit-frame-pointer -gline-tables-only -fsanitize=address,undefined -fsanitize-address-use-after-scope -fsanitize=fuzzer-no-link"
export LEPP_FUZZ_TARGETS=${LEPP_FUZZ_TARGETS:-fuzz_parse} LEPP_BUILD_JOBS=${LEPP_BUILD_JOBS:-2}
mkdir -p "$OUT" "$WORK"
bash .clusterfuzzlite/build.sh >"$tmp/build.log" 2>&1 || { tail -40 "$tmp/build.log"; exit 1; }
for target in $LEPP_FUZZ_TARGETS; do
  test -x "$OUT/$target" && test -s "$OUT/${target}_seed_corpus.zip"
  mkdir -p "$tmp/seeds/$target" && unzip -q "$OUT/${target}_seed_corpus.zip" -d "$tmp/seeds/$target"
  "$OUT/$target" -runs=2000 "$tmp/seeds/$target" >"$tmp/$target.log" 2>&1 || { tail -20 "$tmp/$target.log"; exit 1; }
  echo "ok: $target built by .clusterfuzzlite/build.sh and ran 2000 inputs"
done
