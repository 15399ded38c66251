#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# stdout and stderr sent to one file (`bash scripts/main.sh > log 2>&1`, issue 41):
# no message lands inside a line of the table. `lepp paper` on a small budget
# prints a table of more than 4 KB (more than stdio's buffer, so part of it is
# still buffered when the last message comes) and then "lepp paper: wrote ...":
# every line must be a whole table row or a whole message, and the message last.
# usage: one_file_test.sh LEPP_BINARY SOURCE_DIR
set -u
lepp=$1; src=$2
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
"$lepp" paper --quick --budget 3000 --triangle-budget 3000 --time-limit 5 --no-plots --root "$src" --out "$dir/docs" \
  --work "$dir/work" > "$dir/log" 2>&1; s=$?
[ "$s" -eq 0 ] || { tail -5 "$dir/log"; fail "lepp paper exited $s"; }
# A message inside a line: "lepp paper:" anywhere but at the start of a line.
if grep -n '.lepp paper:' "$dir/log"; then fail "a message inside a line (above)"; fi
[ "$(tail -1 "$dir/log" | cut -c1-17)" = "lepp paper: wrote" ] || { tail -3 "$dir/log"; fail "the last line is not the message"; }
# Every line whole: a run's line (on stderr, indented), a message, or a row of the table
# (problem, method, theta, points, ...); and the table more than stdio's buffer.
python3 - "$dir/log" <<'PY' || fail "a line is cut or mixed (above)"
import re, sys
lines = open(sys.argv[1]).read().splitlines()
table = 0
for l in lines:
    if l.startswith("  ") or l.startswith("lepp paper: "):
        continue
    if l.split()[:3] == ["problem", "method", "theta"] or re.match(r"^\S+ +\S+ +[0-9.]+ +-?[0-9]+ ", l):
        table += len(l) + 1
        continue
    print("not a whole line:", repr(l)); sys.exit(1)
if table <= 4096:
    print(f"the table is {table} bytes, not more than stdio's buffer: the test shows nothing"); sys.exit(1)
PY
grep -q "<table id=\"table1\">" "$dir/docs/paper/index.html" || fail "no docs/paper/index.html with Table 1"
echo "ok: one file, $(wc -l < "$dir/log") lines, none interleaved"
