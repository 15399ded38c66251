#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Quiet logs (issue 32): with stderr a file, as in CI logs and pipes, no subcommand
# writes a carriage return or an escape byte (progress lines rewritten in place are
# for terminals only). Each subcommand runs on a small input, the refines long
# enough to pass their progress ticks (fast engine every 65536 Steiner points,
# reference every 1000). And the progress is still there on a terminal (script(1)
# gives the command one), so the check cannot pass by the progress being gone; there
# `refine -q` (and --json) write none (issue 42), and `lepp audit` writes its own.
# usage: quiet_logs_test.sh LEPP_BINARY SOURCE_DIR
set -u
lepp=$1; src=$2
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
paper=$src/corpus/paper
status=0

# run NAME EXPECTED_EXIT ARGS...: the subcommand with stdout and stderr to files.
run() {
  local name=$1 want=$2; shift 2
  "$lepp" "$@" > "$dir/$name.out" 2> "$dir/$name.err"; local s=$?
  [ "$s" -eq "$want" ] || { cat "$dir/$name.err"; fail "$name: exit $s, expected $want"; }
  # Carriage returns and ESC bytes, counted.
  local bad; bad=$(tr -cd '\r\033' < "$dir/$name.err" | wc -c)
  if [ "$bad" -ne 0 ]; then
    echo "FAIL: $name: $bad carriage return / escape bytes on stderr (not a terminal):"
    od -c "$dir/$name.err" | head -5
    status=1
  else
    echo "ok: $name ($(wc -c < "$dir/$name.err") bytes of stderr, no control characters)"
  fi
}

# steiner NAME MIN: the run added more than MIN Steiner points (so it passed a progress tick).
steiner() {
  local n; n=$(awk '/^Steiner points added/ {print $4}' "$dir/$1.out")
  [ "${n:-0}" -gt "$2" ] || fail "$1: ${n:-no} Steiner points, not past the progress tick at $2"
}
# A 4 x 2 rectangle at max area 5e-5: about 117 thousand Steiner points, past the first tick.
run refine-fast 0 refine "$src/tests/formats/data/labelled.poly" -o "$dir/big" --max-area 5e-5
steiner refine-fast 65536
run refine-json 0 refine "$src/tests/formats/data/labelled.poly" -o "$dir/big" --max-area 5e-5 --json
run refine-reference 0 refine "$paper/A.poly" -o "$dir/a" --engine reference --min-angle 30 --max-area 3e-5
steiner refine-reference 1000
run certify 0 certify "$paper/A.poly" "$dir/a" --min-angle 30
run render 0 render "$dir/a" -o "$dir/a.svg" --highlight bad
run theorems 0 theorems --only Lemma7.AcuteAlpha1AtLeast079Alpha0
grep -q "Lemma 7 (I)(a)" "$dir/theorems.out" || fail "theorems: the statement did not run"
# Each row's progress is one whole line: nothing (RapidCheck's note of its own
# configuration) cuts into it between the row's name and its result.
grep -qx 'Lemma7.AcuteAlpha1AtLeast079Alpha0  *holds (100 cases, [0-9.]* s)' "$dir/theorems.err" ||
  { cat "$dir/theorems.err"; fail "theorems: the row's progress line is not whole"; }
run audit 0 audit --engine fast --theta 25 --cases 2 --out "$dir/audit" --root "$src" -j 1 --no-cache
mkdir -p "$dir/docs"
run paper 0 paper --orders --orders-problems A --orders-angles 30 --orders-random 1 --orders-methods centroid \
  --no-plots --root "$src" --out "$dir/docs" --work "$dir/work"

# On a terminal the progress line is written, and cleared at the end with ESC[K (the
# terminal's own \r\n line ends make a carriage return no evidence of it).
if script -qec "'$lepp' refine '$src/tests/formats/data/labelled.poly' -o '$dir/tty' --max-area 5e-5" \
     "$dir/tty.log" > /dev/null 2>&1 < /dev/null; then
  grep -q 'lepp refine: 65536 Steiner points' "$dir/tty.log" || { status=1; echo "FAIL: no progress line on a terminal"; }
  [ "$(tr -cd '\033' < "$dir/tty.log" | wc -c)" -gt 0 ] || { status=1; echo "FAIL: no ESC[K on a terminal"; }
else
  status=1; echo "FAIL: refine under script(1) failed"; cat "$dir/tty.log"
fi
# -q (and --json, which keeps stdout for the JSON) on a terminal, where the run above
# shows the progress line: none, and no escape byte at all (issue 42).
for quiet in -q --quiet --json; do
  if script -qec "'$lepp' refine '$src/tests/formats/data/labelled.poly' -o '$dir/tty' --max-area 5e-5 $quiet" \
       "$dir/tty-quiet.log" > /dev/null 2>&1 < /dev/null; then
    if grep -q 'lepp refine: [0-9]* Steiner points' "$dir/tty-quiet.log"; then
      status=1; echo "FAIL: $quiet: a progress line on a terminal"
    elif [ "$(tr -cd '\033' < "$dir/tty-quiet.log" | wc -c)" -ne 0 ]; then
      status=1; echo "FAIL: $quiet: escape bytes on a terminal"
    else
      echo "ok: refine $quiet on a terminal: no progress line"
    fi
  else
    status=1; echo "FAIL: refine $quiet under script(1) failed"; cat "$dir/tty-quiet.log"
  fi
done

# The audit's progress line on a terminal (it has no -q: stderr a file or a pipe is its quiet).
script -qec "'$lepp' audit --engine fast --theta 25 --cases 2 --sources paper --compare none --no-cache -j 1 \
  --out '$dir/tty-audit' --root '$src'" "$dir/tty-audit.log" > /dev/null 2>&1 < /dev/null
if grep -q '/2 runs, ' "$dir/tty-audit.log"; then echo "ok: audit progress on a terminal"
else status=1; echo "FAIL: no audit progress line on a terminal"; cat "$dir/tty-audit.log"; fi

[ "$status" -eq 0 ] && echo "ok: quiet logs"
exit "$status"
