#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The browser check (check_page.py, issue 41) can fail: a certificate page of a
# broken mesh passes it as written, and FAILS it with a picture made blank, with
# a picture of zero size, and with one row of the counts removed. Also: a file
# name with <script> in it is text on the page, not a script. Skipped (77)
# without chromium or python3-pil.
# usage: browser_check_test.sh LEPP_BINARY SOURCE_DIR
set -u
lepp=$1; src=$2
check=$src/tests/html/check_page.py
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
command -v chromium > /dev/null && /usr/bin/python3 -c "import PIL" 2> /dev/null || { echo "skipped: needs chromium and python3-pil"; exit 77; }

# A mesh of A broken in several ways (break_mesh.py), certified at 33 degrees.
name="$dir/<script>alert(1)"
"$lepp" refine "$src/corpus/paper/A.poly" -o "$dir/A" --min-angle 30 > /dev/null || fail "refine"
/usr/bin/python3 "$src/tests/html/break_mesh.py" "$dir/A" "$name" || fail "break_mesh.py"
"$lepp" certify "$src/corpus/paper/A.poly" "$name" --min-angle 33 --json --html "$dir/page.html" > "$dir/page.json"
[ $? -eq 1 ] || fail "the broken mesh certified"
grep -q '<script>alert' "$dir/page.html" && fail "the file name is in the page as markup"
grep -q '&lt;script&gt;alert(1)' "$dir/page.html" || fail "the file name is not on the page"

run() {  # run NAME EXPECTED_EXIT PATTERN: the check on page NAME.html
  /usr/bin/python3 "$check" "$dir/$1.html" --json "$dir/page.json" --kind certify --shots "$dir/shots" > "$dir/$1.out" 2>&1
  local s=$?
  cat "$dir/$1.out"
  [ $s -eq "$2" ] || fail "$1: the check exited $s, expected $2"
  [ -z "$3" ] || grep -q "$3" "$dir/$1.out" || fail "$1: the check did not say '$3'"
}
run page 0 ""
[ -s "$dir/shots/page.png" ] || fail "no screenshot kept"

# Broken pages, each from the good one.
/usr/bin/python3 - "$dir" <<'PY'
import re, sys
d = sys.argv[1]
page = open(f"{d}/page.html").read()
# The overview's drawing replaced by a white rectangle of the same size: blank in the screenshot.
at = page.index('<figure class="overview">')
svg = page.index("<svg", at)
end = page.index("</svg>", svg) + len("</svg>")
head = page[svg:page.index(">", svg) + 1]
open(f"{d}/blank.html", "w").write(page[:svg] + head + '<rect width="100%" height="100%" fill="white"/></svg>' + page[end:])
# The histogram's drawing with no size.
at = page.index('<figure class="histogram">')
svg = page.index("<svg", at)
end = page.index("</svg>", svg) + len("</svg>")
open(f"{d}/zero.html", "w").write(page[:svg] + '<svg xmlns="http://www.w3.org/2000/svg" width="0" height="0"></svg>' + page[end:])
# One row of the counts table removed.
rows = re.findall(r'<tr data-reason="[^"]*" data-count="[^"]*">.*?</tr>\n', page)
assert len(rows) >= 2, "the page has fewer than two kinds: the test needs several"
open(f"{d}/missing.html", "w").write(page.replace(rows[0], "", 1))
PY
run blank 1 "blank in the screenshot"
run zero 1 "size 0 x 0"
run missing 1 "missing row"
echo "ok: the browser check passes the page and fails each broken one"
