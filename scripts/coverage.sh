#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Line and branch coverage of core/, impl/, reference/, properties/certify/, audit/ and engines/
# (docs/COVERAGE.md): an instrumented build in its own tree (g++ --coverage -O1),
# measured under (a) the default ctest and (b) the replay of every fuzz corpus,
# then the report, with each uncovered branch's reason from tools/coverage/reasons.txt.
# Opt-in, not part of CI: two full rebuilds (g++ and clang, about 40 CPU-minutes) and
# three test runs.
#
#   scripts/coverage.sh [STEP...]    steps: build ctest fuzz llvm report (default: all five)
# llvm: the default ctest again in a clang build with source-based coverage, whose
# branches are the conditions written in our sources (each if, &&, ||, ?:, loop test,
# true and false). g++'s branches also count what it inlines into our lines: CGAL's
# lazy exact numbers and filtered predicates bring 5 to 40 branches to each arithmetic
# line of the reference and the certifier (interval filter, exact fallback, exception
# cleanup), which no test of ours decides. The report gives both.
# Environment: LEPP_COVERAGE_BUILD (default build-cov), LEPP_COVERAGE_JOBS (default nproc),
#   LEPP_COVERAGE_CORPORA: extra corpus directories per target to replay, as
#   TARGET=DIR entries separated by spaces (default: out/fuzz/TARGET/corpus when it exists);
#   LEPP_COVERAGE_TARGETS: build only these targets, with LEPP_COVERAGE_CTEST_ARGS (e.g. -L, -E)
#   selecting the tests they hold (a cheaper, partial measure: the report says which);
#   LEPP_COVERAGE_EXCLUDE: a ctest -E regex of tests left out (with LEPP_COVERAGE_TARGETS);
#   LEPP_COVERAGE_SPLIT: a ctest -R regex; the report also shows coverage without those tests;
#   LEPP_COVERAGE_BATCH_SECONDS: time cap of each batch of 50 replayed inputs (default 600).
#   LEPP_COVERAGE_CXXFLAGS: optimisation flags of the instrumented g++ build (default -O1);
#   LEPP_COVERAGE_LLVM_BUILD: the clang build of the llvm step (default build-cov-llvm);
#   LEPP_COVERAGE_NICE: niceness of the builds and runs (default 19; 0 to compete evenly with fuzzing at 19).
# Needs gcovr, clang-14 and llvm-14 (llvm-profdata, llvm-cov): Debian's, scripts/install-deps.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
build=${LEPP_COVERAGE_BUILD:-build-cov}
jobs=${LEPP_COVERAGE_JOBS:-$(nproc)}
niceness=${LEPP_COVERAGE_NICE:-19}
out=$build/coverage
steps=("$@")
[ ${#steps[@]} -eq 0 ] && steps=(build ctest fuzz llvm report)
targets=(fuzz_parse fuzz_refine fuzz_differential fuzz_cdt fuzz_audit)

# What is measured: the libraries, not their tests, benchmarks or the CLI; only this
# build's counters (other build trees of the same sources would be merged in).
gcovr_args=("$build" -r "$root" --object-directory "$build" -j "$jobs"
  --filter 'core/' --filter 'impl/' --filter 'reference/' --filter 'properties/certify/' --filter 'audit/' --filter 'engines/'
  --exclude '.*/tests/.*' --exclude '.*/bench/.*'
  --exclude-throw-branches --exclude-unreachable-branches)

zero_counters() { find "$build" -name '*.gcda' -delete; }

for step in "${steps[@]}"; do
  case "$step" in
    build)
      cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=None \
        "-DCMAKE_CXX_FLAGS=${LEPP_COVERAGE_CXXFLAGS:--O1} --coverage -fprofile-update=atomic" \
        -DCMAKE_EXE_LINKER_FLAGS=--coverage -DCMAKE_SHARED_LINKER_FLAGS=--coverage \
        -DLEPP_BUILD_BENCH=OFF >&2
      # LEPP_COVERAGE_TARGETS: build only these (then pass LEPP_COVERAGE_CTEST_ARGS to match).
      nice -n "$niceness" cmake --build "$build" -j "$jobs" ${LEPP_COVERAGE_TARGETS:+--target $LEPP_COVERAGE_TARGETS} >&2
      ;;
    ctest)
      mkdir -p "$out"
      zero_counters
      start=$(date +%s)
      # A failing test still counts its coverage; the report says how many failed.
      # LEPP_COVERAGE_SPLIT=REGEX: first the tests not matching REGEX (measured apart,
      # "without" in the report: what those tests add), then the rest on top.
      set +e
      if [ -n "${LEPP_COVERAGE_SPLIT:-}" ]; then
        nice -n "$niceness" ctest --test-dir "$build" -j "$jobs" --timeout 1200 ${LEPP_COVERAGE_CTEST_ARGS:-} -E "$LEPP_COVERAGE_SPLIT${LEPP_COVERAGE_EXCLUDE:+|$LEPP_COVERAGE_EXCLUDE}" > "$out/ctest.log" 2>&1
        echo $? > "$out/ctest.status"
        set -e
        gcovr "${gcovr_args[@]}" --json "$out/ctest-without.json" >&2
        set +e
        nice -n "$niceness" ctest --test-dir "$build" -j "$jobs" --timeout 1200 ${LEPP_COVERAGE_CTEST_ARGS:-} -R "$LEPP_COVERAGE_SPLIT" >> "$out/ctest.log" 2>&1
        echo $(( $? | $(cat "$out/ctest.status") )) > "$out/ctest.status"
      else
        rm -f "$out/ctest-without.json"
        nice -n "$niceness" ctest --test-dir "$build" -j "$jobs" --timeout 1200 ${LEPP_COVERAGE_CTEST_ARGS:-} \
          ${LEPP_COVERAGE_EXCLUDE:+-E "$LEPP_COVERAGE_EXCLUDE"} > "$out/ctest.log" 2>&1
        echo $? > "$out/ctest.status"
      fi
      set -e
      echo $(( $(date +%s) - start )) > "$out/ctest.seconds"
      tail -3 "$out/ctest.log" >&2
      gcovr "${gcovr_args[@]}" --json "$out/ctest.json" --txt "$out/ctest.txt" >&2
      ;;
    fuzz)
      mkdir -p "$out"
      zero_counters
      : > "$out/fuzz.log"
      for t in "${targets[@]}"; do
        dirs=()
        for d in corpus/fuzz/$t corpus/regressions/$t "out/fuzz/$t/corpus"; do [ -d "$d" ] && dirs+=("$d"); done
        for entry in ${LEPP_COVERAGE_CORPORA:-}; do [ "${entry%%=*}" = "$t" ] && dirs+=("${entry#*=}"); done
        [ ${#dirs[@]} -eq 0 ] && continue
        echo "== $t: ${dirs[*]}" >> "$out/fuzz.log"
        # In batches of 50 inputs, each batch capped at LEPP_COVERAGE_BATCH_SECONDS (default 600):
        # a unit that runs away costs its batch only (a killed process writes no counters).
        find "${dirs[@]}" -maxdepth 1 -type f ! -name '*.md' -print0 | sort -z |
          xargs -0 -r -n 50 timeout "${LEPP_COVERAGE_BATCH_SECONDS:-600}" nice -n "$niceness" "$build/fuzz/${t}_replay" \
            >> "$out/fuzz.log" 2>&1 || echo "($t: some batch reported findings or timed out)" >> "$out/fuzz.log"
        # Open findings are replayed too (they still report theirs): their paths count.
        if [ -d "corpus/regressions/$t/open" ]; then
          timeout "${LEPP_COVERAGE_BATCH_SECONDS:-600}" nice -n "$niceness" "$build/fuzz/${t}_replay" --expect-finding \
            "corpus/regressions/$t/open" >> "$out/fuzz.log" 2>&1 || true
        fi
      done
      grep -E '^(==|replayed)' "$out/fuzz.log" >&2 || true
      gcovr "${gcovr_args[@]}" --json "$out/fuzz.json" --txt "$out/fuzz.txt" >&2
      ;;
    llvm)
      lbuild=${LEPP_COVERAGE_LLVM_BUILD:-$build-llvm}
      CC=clang CXX=clang++ cmake -S . -B "$lbuild" -G Ninja -DCMAKE_BUILD_TYPE=None \
        "-DCMAKE_CXX_FLAGS=-O1 -fprofile-instr-generate -fcoverage-mapping" \
        -DCMAKE_EXE_LINKER_FLAGS=-fprofile-instr-generate -DLEPP_BUILD_BENCH=OFF >&2
      nice -n "$niceness" cmake --build "$lbuild" -j "$jobs" >&2
      mkdir -p "$out"
      rm -rf "$lbuild/profiles"
      mkdir -p "$lbuild/profiles"
      start=$(date +%s)
      # %4m: a pool of four files per binary, merged online (the tests run in parallel).
      set +e
      LLVM_PROFILE_FILE="$root/$lbuild/profiles/%4m.profraw" nice -n "$niceness" \
        ctest --test-dir "$lbuild" -j "$jobs" --timeout 1200 > "$out/llvm-ctest.log" 2>&1
      set -e
      echo $(( $(date +%s) - start )) > "$out/llvm-ctest.seconds"
      tail -3 "$out/llvm-ctest.log" >&2
      llvm-profdata merge -sparse "$lbuild"/profiles/*.profraw -o "$out/llvm.profdata"
      # Every instrumented program the tests ran: the test executables and the CLI.
      mapfile -t objects < <(find "$lbuild" -type f -perm -u+x ! -name '*.so*' ! -path '*/CMakeFiles/*' \
        -exec sh -c 'head -c 4 "$1" | grep -q ELF' _ {} \; -print | sort)
      args=()
      for o in "${objects[@]}"; do args+=(-object "$o"); done
      llvm-cov export -format=text -instr-profile "$out/llvm.profdata" "${args[@]}" \
        -ignore-filename-regex='(^/usr/|/tests/|/bench/|/fuzz/|/cli/|/examples/|_deps/)' > "$out/llvm-ctest.raw.json"
      python3 tools/coverage/llvm_json.py "$out/llvm-ctest.raw.json" --root "$root" > "$out/llvm-ctest.json"
      rm -f "$out/llvm-ctest.raw.json"
      ;;
    report)
      gcovr -r "$root" --add-tracefile "$out/ctest.json" --add-tracefile "$out/fuzz.json" --json "$out/all.json" >&2
      python3 tools/coverage/report.py --ctest "$out/ctest.json" --fuzz "$out/fuzz.json" --all "$out/all.json" \
        --reasons tools/coverage/reasons.txt --ctest-seconds "$(cat "$out/ctest.seconds" 2>/dev/null || echo '?')" \
        --ctest-log "$out/ctest.log" --flags="${LEPP_COVERAGE_CXXFLAGS:--O1}" --build "$build" \
        $( [ -f "$out/llvm-ctest.json" ] && echo --source-branches "$out/llvm-ctest.json" ) --ctest-args "${LEPP_COVERAGE_CTEST_ARGS:-}${LEPP_COVERAGE_EXCLUDE:+ -E $LEPP_COVERAGE_EXCLUDE}" ${LEPP_COVERAGE_SPLIT:+--without "$out/ctest-without.json" --split "$LEPP_COVERAGE_SPLIT"} \
        > docs/COVERAGE.md
      echo "wrote docs/COVERAGE.md" >&2
      ;;
    *) echo "coverage.sh: unknown step '$step' (build ctest fuzz llvm report)" >&2; exit 2 ;;
  esac
done
