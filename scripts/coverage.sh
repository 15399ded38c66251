#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Line and branch coverage of core/, impl/, reference/ and properties/certify/
# (docs/COVERAGE.md): an instrumented build in its own tree (g++ --coverage -O1 -fno-inline),
# measured under (a) the default ctest and (b) the replay of every fuzz corpus,
# then the report, with each uncovered branch's reason from tools/coverage/reasons.txt.
# Opt-in, not part of CI: a full rebuild (about 20 CPU-minutes) plus two test runs.
#
#   scripts/coverage.sh [STEP...]    steps: build ctest fuzz report (default: all four)
# Environment: LEPP_COVERAGE_BUILD (default build-cov), LEPP_COVERAGE_JOBS (default nproc),
#   LEPP_COVERAGE_CORPORA: extra corpus directories per target to replay, as
#   TARGET=DIR entries separated by spaces (default: out/fuzz/TARGET/corpus when it exists);
#   LEPP_COVERAGE_TARGETS: build only these targets, with LEPP_COVERAGE_CTEST_ARGS (e.g. -L, -E)
#   selecting the tests they hold (a cheaper, partial measure: the report says which);
#   LEPP_COVERAGE_EXCLUDE: a ctest -E regex of tests left out (with LEPP_COVERAGE_TARGETS);
#   LEPP_COVERAGE_SPLIT: a ctest -R regex; the report also shows coverage without those tests;
#   LEPP_COVERAGE_BATCH_SECONDS: time cap of each batch of 50 replayed inputs (default 600).
#   LEPP_COVERAGE_CXXFLAGS: optimisation flags of the instrumented build (default -O1 -fno-inline);
#   LEPP_COVERAGE_INLINED: a gcovr JSON of the default ctest in a build that inlines, shown for comparison;
#   LEPP_COVERAGE_NICE: niceness of the builds and runs (default 19; 0 to compete evenly with fuzzing at 19).
# Needs gcovr (Debian's, scripts/install-deps.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
build=${LEPP_COVERAGE_BUILD:-build-cov}
jobs=${LEPP_COVERAGE_JOBS:-$(nproc)}
niceness=${LEPP_COVERAGE_NICE:-19}
out=$build/coverage
steps=("$@")
[ ${#steps[@]} -eq 0 ] && steps=(build ctest fuzz report)
targets=(fuzz_parse fuzz_refine fuzz_differential fuzz_cdt)

# What is measured: the libraries, not their tests, benchmarks or the CLI.
gcovr_args=(-r "$root" --object-directory "$build" -j "$jobs"
  --filter 'core/' --filter 'impl/' --filter 'reference/' --filter 'properties/certify/'
  --exclude '.*/tests/.*' --exclude '.*/bench/.*'
  --exclude-throw-branches --exclude-unreachable-branches)

zero_counters() { find "$build" -name '*.gcda' -delete; }

for step in "${steps[@]}"; do
  case "$step" in
    build)
      # -fno-inline: a branch is counted on the line that decides it. Inlined, CGAL's
      # lazy exact numbers put 5 to 30 of their own branches (interval filter, exact
      # fallback, reference counts) on every arithmetic line of the reference and the
      # certifier; not inlined, those branches stay in CGAL's headers, outside the measure.
      cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=None \
        "-DCMAKE_CXX_FLAGS=${LEPP_COVERAGE_CXXFLAGS:--O1 -fno-inline} --coverage -fprofile-update=atomic" \
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
    report)
      gcovr -r "$root" --add-tracefile "$out/ctest.json" --add-tracefile "$out/fuzz.json" --json "$out/all.json" >&2
      python3 tools/coverage/report.py --ctest "$out/ctest.json" --fuzz "$out/fuzz.json" --all "$out/all.json" \
        --reasons tools/coverage/reasons.txt --ctest-seconds "$(cat "$out/ctest.seconds" 2>/dev/null || echo '?')" \
        --ctest-log "$out/ctest.log" --flags="${LEPP_COVERAGE_CXXFLAGS:--O1 -fno-inline}" --build "$build" \
        ${LEPP_COVERAGE_INLINED:+--inlined "$LEPP_COVERAGE_INLINED"} --ctest-args "${LEPP_COVERAGE_CTEST_ARGS:-}${LEPP_COVERAGE_EXCLUDE:+ -E $LEPP_COVERAGE_EXCLUDE}" ${LEPP_COVERAGE_SPLIT:+--without "$out/ctest-without.json" --split "$LEPP_COVERAGE_SPLIT"} \
        > docs/COVERAGE.md
      echo "wrote docs/COVERAGE.md" >&2
      ;;
    *) echo "coverage.sh: unknown step '$step' (build ctest fuzz report)" >&2; exit 2 ;;
  esac
done
