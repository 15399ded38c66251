#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The HTML reports in a real browser (issue 41): Debian's headless Chromium opens
# the pages of a mesh that certifies, a broken mesh with violations of several
# kinds, an audit with findings, a merged sharded audit, a certificate of
# 10^6 triangles and `lepp paper`'s page, and tests/html/check_page.py checks each
# against its JSON report: the rows and counts in the DOM, every picture with a nonzero size and
# not blank in a screenshot, no console error, and the large page loaded within
# 5 seconds. The pages, JSON reports and screenshots stay in build/html-check/.
# Then the check itself must fail on broken pages (tests/html/browser_check_test.sh).
# LEPP_BUILD_DIR overrides the build directory (default build/).
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${LEPP_BUILD_DIR:-build}
lepp=$build/cli/lepp
mesher=$build/audit/tests/mesher/lepp_test_mesher
out=$build/html-check
rm -rf "$out"
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
check() { /usr/bin/python3 tests/html/check_page.py "$@" --shots "$out/screenshots"; }
expect() {  # expect STATUS COMMAND...: the command's exit status must be STATUS
  local want=$1; shift
  set +e; "$@"; local s=$?; set -e
  [ "$s" -eq "$want" ] || { echo "FAIL: exit $s, expected $want: $*"; exit 1; }
}

echo "-- a mesh that certifies"
"$lepp" refine corpus/paper/A.poly -o "$work/A" --min-angle 30 > /dev/null
expect 0 "$lepp" certify corpus/paper/A.poly "$work/A" --min-angle 30 --json --html "$out/certified.html" > "$out/certified.json"
check "$out/certified.html" --kind certify --json "$out/certified.json"

echo "-- a broken mesh: a vertex moved, a triangle dropped, certified at 33 degrees"
/usr/bin/python3 tests/html/break_mesh.py "$work/A" "$work/broken"
expect 1 "$lepp" certify corpus/paper/A.poly "$work/broken" --min-angle 33 --json --html "$out/broken.html" > "$out/broken.json"
/usr/bin/python3 -c 'import json,sys; c=json.load(open(sys.argv[1]))["violation_counts"]; k=[r for r,n in c.items() if n]; assert len(k)>=3, c; print("kinds:", ", ".join(k))' "$out/broken.json"
check "$out/broken.html" --kind certify --json "$out/broken.json"

echo "-- an audit with findings: a program with two deviations, and one that skips flips (shrunk)"
cmd="$mesher {in} {out} {theta} {method} --bug area-centroid --bug other-second-longest"
expect 1 "$lepp" audit --cmd "$cmd" --inputs corpus/paper --theta 25,30 --max-findings 2 --no-shrink --compare none -j 2 \
  --out "$work/audit-out" --json-file "$out/audit.json" --html "$out/audit.html" > /dev/null
check "$out/audit.html" --kind audit --json "$out/audit.json"
expect 1 "$lepp" audit --cmd "$mesher {in} {out} {theta} {method} --bug no-flips" --sources gen --seed 3 --theta 25 --cases 8 \
  --max-findings 1 --shrink-seconds 20 --compare none -j 2 --out "$work/shrunk-out" --json-file "$out/audit-shrunk.json" \
  --html "$out/audit-shrunk.html" > /dev/null
check "$out/audit-shrunk.html" --kind audit --json "$out/audit-shrunk.json"

echo "-- a sharded audit, merged (bare --json on stdout)"
for k in 1 2; do
  expect 1 "$lepp" audit --cmd "$cmd" --inputs corpus/paper --theta 25,30 --max-findings 2 --no-shrink --compare none -j 2 \
    --shard "$k/2" --out "$work/shard-$k" --json > "$work/shard-$k.json"
done
expect 1 "$lepp" audit merge "$work/shard-1.json" "$work/shard-2.json" --out "$work/merged-out" --json \
  --html "$out/merged.html" > "$out/merged.json"
check "$out/merged.html" --kind audit --json "$out/merged.json"

echo "-- a certificate of 10^6 triangles: the page loads within 5 s"
"$lepp" refine tests/formats/data/labelled.poly -o "$work/big" --max-area 1e-5 --min-angle 20 > /dev/null
expect 0 "$lepp" certify tests/formats/data/labelled.poly "$work/big" --min-angle 20 --json --html "$out/large.html" > "$out/large.json"
/usr/bin/python3 -c 'import json,sys; t=json.load(open(sys.argv[1]))["statistics"]["triangles"]; assert t>=10**6, t; print("triangles:", t)' "$out/large.json"
ls -l "$out/large.html"
check "$out/large.html" --kind certify --json "$out/large.json" --max-load-ms 5000

echo "-- lepp paper's page (a quick study on a small budget, with its plots)"
"$lepp" paper --quick --budget 3000 --triangle-budget 3000 --time-limit 5 --root . --out "$work/docs" --work "$work/paper" > /dev/null
cp "$work/docs/paper/index.html" "$out/paper.html"  # self-contained: it reads nothing beside it
check "$out/paper.html" --kind paper

echo "-- the check fails on broken pages"
bash tests/html/browser_check_test.sh "$lepp" "$PWD"
echo "ok: every page passed in Chromium; screenshots in $out/screenshots"
