#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# `lepp audit merge` refuses the shards of two audits with different settings (issue 42):
# shard 1/2 under --arithmetic exact and shard 2/2 under --arithmetic double judge the
# same steps differently, so merging them would make a report no audit gives. Exit 2,
# one line naming the setting and both values, no report on stdout. The same two shards
# under one setting merge (exit 0 or 1), so the refusal is the setting's doing.
# (Every other setting is covered by audit_decision_tests' ShardSettings.)
# usage: audit_merge_settings_test.sh LEPP_BINARY SOURCE_DIR
set -u
lepp=$1; src=$2
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

shard() {  # shard K ARITHMETIC
  "$lepp" audit --engine fast --theta 25 --cases 2 --sources paper --compare none --no-cache -j 1 \
    --root "$src" --shard "$1/2" --arithmetic "$2" --out "$dir/out-$1-$2" --json > "$dir/shard-$1-$2.json" 2> "$dir/shard-$1-$2.err"
  local s=$?
  [ "$s" -eq 0 ] || [ "$s" -eq 1 ] || { cat "$dir/shard-$1-$2.err"; fail "shard $1 ($2): exit $s"; }
}
shard 1 exact; shard 2 exact; shard 2 double

"$lepp" audit merge "$dir/shard-1-exact.json" "$dir/shard-2-exact.json" --out "$dir/merged" > "$dir/same.md" 2> "$dir/same.err"
s=$?
[ "$s" -eq 0 ] || [ "$s" -eq 1 ] || { cat "$dir/same.err"; fail "shards of one audit: exit $s"; }
echo "ok: shards of one setting merge (exit $s)"

"$lepp" audit merge "$dir/shard-1-exact.json" "$dir/shard-2-double.json" --out "$dir/mixed" > "$dir/mixed.md" 2> "$dir/mixed.err"
s=$?
[ "$s" -eq 2 ] || { cat "$dir/mixed.err"; fail "exact and double shards: exit $s, expected 2"; }
[ "$(wc -l < "$dir/mixed.err")" -eq 1 ] || { cat "$dir/mixed.err"; fail "expected one line on stderr"; }
grep -qF 'arithmetic is "exact" in one, "double" in the other' "$dir/mixed.err" || { cat "$dir/mixed.err"; fail "the message does not name both values"; }
[ ! -s "$dir/mixed.md" ] || fail "a report on stdout after the refusal"
echo "ok: exact and double shards refused: $(cat "$dir/mixed.err")"
