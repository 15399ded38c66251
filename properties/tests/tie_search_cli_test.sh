#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# --tie-search-states (issue 39; docs/CERTIFIER.md section 5c) through the command:
# its default is 1024 in refine, certify and audit; refine passes it to the engine,
# certify names a claim undecided at its bound, rejects it with a witness without one,
# and certifies the mesh made at 4096; audit passes it on and reports it.
# usage: tie_search_cli_test.sh LEPP_BINARY SOURCE_DIR
set -u
lepp=$1; src=$2
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
in=$src/corpus/regressions/precision/tie-finding-subnormal-midpoint.poly

# The default, as each command states it in its help.
for cmd in refine certify audit; do
  "$lepp" $cmd --help | grep -q -- '--tie-search-states UINT=1024$' || fail "$cmd --help: no --tie-search-states default 1024"
done

# The centroid method at 10 degrees: at the default both engines leave a claim the
# certifier at 1024 calls undecided, and the same with --tie-search-states 1024.
for engine in fast reference; do
  "$lepp" refine "$in" -o "$dir/d-$engine" --min-angle 10 --engine $engine -q --json > "$dir/d-$engine.json"; s=$?
  [ $s -eq 3 ] || fail "refine ($engine) at the default: exit $s (unimprovable is 3)"
  grep -q '"tie_search_states": 1024' "$dir/d-$engine.json" || fail "refine ($engine): no tie_search_states 1024 in --json"
done
cmp -s "$dir/d-fast.node" "$dir/d-reference.node" || fail "the engines' meshes differ at the default"
"$lepp" certify "$in" "$dir/d-fast" --min-angle 10 > "$dir/out"; s=$?
[ $s -eq 1 ] || { cat "$dir/out"; fail "certify at the default: exit $s"; }
grep -q 'stopped undecided at bound 1024 Lepp states' "$dir/out" || { cat "$dir/out"; fail "no claim undecided at bound 1024"; }
grep -q 'undecided at bound 1024 Lepp states$' "$dir/out" || { cat "$dir/out"; fail "no summary line of the claims"; }
"$lepp" certify "$in" "$dir/d-fast" --min-angle 10 --tie-search-states 1024 > "$dir/out2"
cmp -s "$dir/out" "$dir/out2" || fail "certify: the default is not --tie-search-states 1024"

# A recorded known violation: with no bound the certifier rejects the claim with a witness.
"$lepp" certify "$in" "$dir/d-fast" --min-angle 10 --tie-search-states 0 > "$dir/out"; s=$?
[ $s -eq 1 ] || { cat "$dir/out"; fail "certify with no bound: exit $s"; }
grep -q '^unimprovable-rule-fails: .* can be inserted: witness point (.*) = (0x.*), rounding .*, branch .*: Lepp triangle ' "$dir/out" ||
  { cat "$dir/out"; fail "no witness printed"; }
"$lepp" certify "$in" "$dir/d-fast" --min-angle 10 --tie-search-states 0 --json > "$dir/out.json"
python3 - "$dir/out.json" <<'EOF' || fail "certify --json: the claim's outcome and witness"
import json, sys
r = json.load(open(sys.argv[1]))
assert r["tie_search_states"] == 0 and not r["certified"], r["tie_search_states"]
rejected = [c for c in r["precision_claims"] if c["outcome"] == "rejected"]
assert rejected and r["precision_claim_counts"]["rejected"] == len(rejected), r["precision_claims"]
w = rejected[0]["witness"]
assert [float.fromhex(h) for h in w["point_hex"]] == w["point"], w
assert w["lepp"][0] == rejected[0]["triangle"] and len(w["lepp"]) == len(w["longest"]), w
EOF
# A time limit already passed: every claim undecided at the time limit.
"$lepp" certify "$in" "$dir/d-fast" --min-angle 10 --tie-search-states 0 --time-limit 1e-9 > "$dir/out"; s=$?
[ $s -eq 1 ] && grep -q 'stopped undecided at the time limit' "$dir/out" || { cat "$dir/out"; fail "--time-limit"; }

# At 4096 states in the engine and the certifier the mesh certifies (and it differs); both
# engines at 4096: impl_precision_tests, TieSearchBound.*.
"$lepp" refine "$in" -o "$dir/w" --min-angle 10 --tie-search-states 4096 -q > /dev/null; s=$?
[ $s -eq 0 ] || [ $s -eq 3 ] || fail "refine at 4096: exit $s"
"$lepp" certify "$in" "$dir/w" --min-angle 10 --tie-search-states 4096 > "$dir/out"; s=$?
[ $s -eq 0 ] || { cat "$dir/out"; fail "certify at 4096: exit $s"; }
cmp -s "$dir/d-fast.node" "$dir/w.node" && fail "refine ignores --tie-search-states"

# The audit of lepp's fast engine on tie-finding.poly at 20 degrees alone: at the default
# its certificate proves the triangles left at double precision exempt and every row
# holds; at one Lepp state the engine and the certificate stop early and min-angle fails.
mkdir -p "$dir/inputs" && cp "$src/corpus/regressions/precision/tie-finding.poly" "$dir/inputs/"
for states in 1024 1; do
  "$lepp" audit --engine fast --inputs "$dir/inputs" --sources "" --theta 20 --compare none --no-shrink --no-cache -j 1 \
    --out "$dir/audit-$states" --tie-search-states $states --json > "$dir/audit-$states.json" 2> "$dir/audit.err"
  python3 - "$dir/audit-$states.json" $states <<'EOF' || { cat "$dir/audit.err"; fail "audit at $states"; }
import json, sys
r, states = json.load(open(sys.argv[1])), int(sys.argv[2])
assert r["tie_search_states"] == states, r["tie_search_states"]
row = next(x for x in r["rows"] if x["check"] == "min-angle")
assert row["runs"] == 1 and (row["failed"] == 0) == (states == 1024), (states, row)
assert (r["precision_exempt_triangles"] > 0) == (states == 1024), r["precision_exempt_triangles"]
EOF
done
echo "OK"
