#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# `lepp certify` exit statuses on files: 0 certified, 1 violations (listed), 2 unreadable.
# usage: certify_cli_test.sh LEPP_BINARY SOURCE_DIR
set -u
lepp=$1; src=$2
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
"$lepp" refine "$src/corpus/paper/A.poly" -o "$dir/a" --min-angle 30 -q > /dev/null || fail "refine"
"$lepp" certify "$src/corpus/paper/A.poly" "$dir/a" --min-angle 30 > "$dir/out" ; s=$?
[ $s -eq 0 ] || { cat "$dir/out"; fail "certified mesh: exit $s"; }
grep -q '^CERTIFIED' "$dir/out" || fail "no CERTIFIED line"
"$lepp" certify "$src/corpus/paper/A.poly" "$dir/a" --min-angle 30 --json | grep -q '"certified": true' || fail "json"
# Clockwise: swap two corners of the first triangle (line 2 of the .ele).
awk 'NR==2 {t=$3; $3=$4; $4=t} {print}' "$dir/a.ele" > "$dir/b.ele"; cp "$dir/a.node" "$dir/b.node"; cp "$dir/a.poly" "$dir/b.poly"
"$lepp" certify "$src/corpus/paper/A.poly" "$dir/b" > "$dir/out"; s=$?
[ $s -eq 1 ] || fail "clockwise triangle: exit $s"
grep -q '^not-counter-clockwise: triangle 0' "$dir/out" || { cat "$dir/out"; fail "violation not listed"; }
"$lepp" certify "$src/corpus/paper/A.poly" "$dir/missing" > /dev/null 2>&1; s=$?
[ $s -eq 2 ] || fail "missing mesh: exit $s"
# The small-input-angle exemption (docs/CERTIFIER.md): lepp's mesh of a 1-degree triangle,
# its own unimprovable list removed, fails at 30 degrees and certifies with the flag.
"$lepp" refine "$src/corpus/hostile/small-input-angle.poly" -o "$dir/s" --min-angle 30 -q > /dev/null; s=$?
[ $s -eq 3 ] || fail "refine small angle: exit $s (outcome unimprovable is 3)"
rm -f "$dir/s.unimprovable"
"$lepp" certify "$src/corpus/hostile/small-input-angle.poly" "$dir/s" --min-angle 30 > "$dir/out"; s=$?
[ $s -eq 1 ] || { cat "$dir/out"; fail "small angle without the flag: exit $s"; }
"$lepp" certify "$src/corpus/hostile/small-input-angle.poly" "$dir/s" --min-angle 30 --exempt-small-input-angles > "$dir/out"; s=$?
[ $s -eq 0 ] || { cat "$dir/out"; fail "small angle with the flag: exit $s"; }
grep -q 'triangles below theta exempt' "$dir/out" || { cat "$dir/out"; fail "no exempt line"; }
"$lepp" certify "$src/corpus/hostile/small-input-angle.poly" "$dir/s" --min-angle 30 --exempt-small-input-angles --json > "$dir/out"
grep -q '"exempt_count": [1-9]' "$dir/out" || { cat "$dir/out"; fail "json exempt_count"; }
# A fuzz_refine finding (data/small_angles_apex_chain.poly): both engines stop on the edge
# floor near an apex with segments 0.22 and 2.1 degrees apart; the chain walk of one
# segment must not follow another's listed edge there (docs/CERTIFIER.md section 3).
for engine in reference fast; do
  "$lepp" refine "$src/properties/tests/data/small_angles_apex_chain.poly" -o "$dir/c" --engine $engine --method centroid \
    --min-angle 34 --order lifo --edge-floor 4.452741724487821e-08 --max-steiner 10000 -q > /dev/null; s=$?
  [ $s -eq 3 ] || fail "refine apex chain ($engine): exit $s (edge-floor is 3)"
  "$lepp" certify "$src/properties/tests/data/small_angles_apex_chain.poly" "$dir/c" > "$dir/out"; s=$?
  [ $s -eq 0 ] || { cat "$dir/out"; fail "apex chain ($engine): exit $s"; }
done
# Size bounds (docs/CERTIFIER.md section 7): lepp's mesh made with --region-areas certifies
# with it; the mesh made without is rejected for area-above-bound, with --region-areas
# (naming the region) and with --max-area (in the JSON too).
ra="$src/corpus/triangle-formats/region-areas.poly"
"$lepp" refine "$ra" -o "$dir/ra" --region-areas -q > /dev/null || fail "refine --region-areas"
"$lepp" refine "$ra" -o "$dir/rn" -q > /dev/null 2>&1 || fail "refine without the bounds"
"$lepp" certify "$ra" "$dir/ra" --min-angle 30 --region-areas > "$dir/out" 2> /dev/null; s=$?
[ $s -eq 0 ] || { cat "$dir/out"; fail "mesh with the region bounds: exit $s"; }
grep -q '^size bound: [1-9][0-9]* triangles checked, the bounds of 5 regions' "$dir/out" || { cat "$dir/out"; fail "no size bound line"; }
grep -q '^  region 4: in-hole, applies to nothing' "$dir/out" || { cat "$dir/out"; fail "region in the hole not said"; }
"$lepp" certify "$ra" "$dir/rn" --min-angle 30 --region-areas > "$dir/out" 2> /dev/null; s=$?
[ $s -eq 1 ] || { cat "$dir/out"; fail "mesh without the region bounds: exit $s"; }
grep -q '^area-above-bound: triangle [0-9]* .* above the bound 0.05 of region 1 (line 41 of ' "$dir/out" || { cat "$dir/out"; fail "region violation not listed"; }
"$lepp" certify "$ra" "$dir/rn" --max-area 0.2 --max-listed 2 --json > "$dir/out" 2> /dev/null; s=$?
[ $s -eq 1 ] || fail "mesh without --max-area: exit $s"
python3 -c '
import json, sys
j = json.load(open(sys.argv[1]))
assert not j["certified"]
assert j["size_bound"]["max_area"] == 0.2 and j["size_bound"]["triangles_checked"] > 2, j["size_bound"]
assert j["violation_counts"]["area-above-bound"] == j["statistics"]["triangles"], j["violation_counts"]
listed = [v for v in j["violations"] if v["reason"] == "area-above-bound"]
assert len(listed) == 2 and listed[0]["check"] == "size-bound" and listed[0]["region"] == -1, listed
' "$dir/out" || { cat "$dir/out"; fail "json size bound"; }
"$lepp" certify "$ra" "$dir/ra" --max-area 0.2 --region-areas > /dev/null 2>&1; s=$?
[ $s -eq 1 ] || fail "mesh with the region bounds, checked with a smaller global one too: exit $s"
# --precision-ties-by-ids (docs/CERTIFIER.md section 5c, Finding): lepp 0.2's engines left a triangle
# of tie-finding.poly at 20 degrees that another resolution of an exact length tie could refine
# (stored: tie-finding-v0.2-20/); the strict rule rejects that claim, lepp's old tie rule accepts it.
# Today's engines try every resolution (ALGORITHM.md section 8b): their mesh certifies strictly.
prec="$src/corpus/regressions/precision"
tie="$prec/tie-finding.poly"
"$lepp" certify "$tie" "$prec/tie-finding-v0.2-20/out" --min-angle 20 --exempt-precision-limited > "$dir/out"; s=$?
[ $s -eq 1 ] || { cat "$dir/out"; fail "tie-finding 0.2 mesh, strict: exit $s"; }
grep -q '^unimprovable-rule-fails: .*listed as limited by double precision' "$dir/out" || { cat "$dir/out"; fail "tie-finding: no rule-fails line"; }
"$lepp" certify "$tie" "$prec/tie-finding-v0.2-20/out" --min-angle 20 --exempt-precision-limited --precision-ties-by-ids > "$dir/out"; s=$?
[ $s -eq 0 ] || { cat "$dir/out"; fail "tie-finding 0.2 mesh, ties by ids: exit $s"; }
for engine in fast reference; do
  "$lepp" refine "$tie" -o "$dir/tie-$engine" --min-angle 20 --engine $engine -q > /dev/null; s=$?
  [ $s -eq 0 ] || [ $s -eq 3 ] || fail "refine tie-finding ($engine): exit $s"
  "$lepp" certify "$tie" "$dir/tie-$engine" --min-angle 20 --exempt-precision-limited > "$dir/out"; s=$?
  [ $s -eq 0 ] || { cat "$dir/out"; fail "tie-finding ($engine), strict: exit $s"; }
done
cmp -s "$dir/tie-fast.node" "$dir/tie-reference.node" && cmp -s "$dir/tie-fast.ele" "$dir/tie-reference.ele" ||
  fail "tie-finding: the engines' meshes differ"
# The same at subnormal coordinates with the midpoint method (campaign of 2026-12-02, e792c892):
# a length tie of 25 u^2 in the Lepp, where the ids' resolution ends within the precision floor.
tie="$prec/tie-finding-subnormal-midpoint.poly"
"$lepp" refine "$tie" -o "$dir/tie2" --min-angle 20 --method midpoint -q > /dev/null; s=$?
[ $s -eq 0 ] || [ $s -eq 3 ] || fail "refine tie-finding-subnormal-midpoint: exit $s"
"$lepp" certify "$tie" "$dir/tie2" --min-angle 20 --method midpoint --exempt-precision-limited > "$dir/out"; s=$?
[ $s -eq 0 ] || { cat "$dir/out"; fail "tie-finding-subnormal-midpoint, strict: exit $s"; }
# The pictures (--svg, --svg-zoom): the notch mesh that overlaps itself (corpus/regressions/precision),
# its crossing chain edges drawn in red and named in the legend; the zoom is a window (smaller
# viewBox content: fewer triangles drawn). The verdict and stdout are unchanged by drawing.
notch=$src/corpus/regressions/precision
"$lepp" certify "$notch/notch-overlap.poly" "$notch/notch-overlap-fast-25/out" --min-angle 25 --svg "$dir/n.svg" --svg-zoom "$dir/nz.svg" \
  > "$dir/out" 2> "$dir/err"; s=$?
[ $s -eq 1 ] || { cat "$dir/out" "$dir/err"; fail "notch overlap with --svg: exit $s"; }
grep -q '^chain-edges-meet: ' "$dir/out" || { cat "$dir/out"; fail "notch overlap: no chain-edges-meet line"; }
grep -q "wrote $dir/n.svg" "$dir/err" && grep -q "wrote $dir/nz.svg" "$dir/err" || { cat "$dir/err"; fail "no 'wrote' lines"; }
for f in n nz; do
  grep -q '<svg' "$dir/$f.svg" && grep -q 'chain-edges-meet' "$dir/$f.svg" || fail "$f.svg: no drawing or no legend"
  grep -q 'red' "$dir/$f.svg" || fail "$f.svg: nothing highlighted"
done
grep -q '>window \[' "$dir/nz.svg" && ! grep -q '>window \[' "$dir/n.svg" || fail "nz.svg is not a window, or n.svg is"
"$lepp" certify "$src/corpus/paper/A.poly" "$dir/a" --min-angle 30 --svg "$dir/a.svg" > /dev/null 2>&1; s=$?
[ $s -eq 0 ] && grep -q '<svg' "$dir/a.svg" || fail "certified mesh with --svg: exit $s"
echo "OK"
