#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Issue 30: `lepp audit` never dies on a program's output. The recorded output of
# a mesher with a deliberate point-choice bug (inputs/audit-fpe: its mesh and trace
# for the triangle tri.poly) once ended the audit with SIGFPE (exit 136, no report):
# the deviation catalogue took the circumcenter of a flat triangle in the replay's
# mesh. Now every run gives a report with a named finding (or an internal-error
# finding), with and without shrinking; never a signal.
# usage: audit_recorded_test.sh LEPP_BINARY SOURCE_DIR
set -u
lepp=$1; src=$2
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
rec="$src/audit/tests/inputs/audit-fpe"
cmd="$src/audit/tests/programs/recorded.sh $rec {in} {out}"

# The run as recorded, at every theta: exit 1 (findings) or 3 (internal errors), a report.
"$lepp" audit --cmd "$cmd" --inputs "$rec/tri.poly" --theta 20,25,30 --compare none --no-shrink \
  --out "$dir/found" --json > "$dir/found.json"; s=$?
[ $s -eq 1 ] || [ $s -eq 3 ] || fail "recorded run: exit $s (136 is the SIGFPE of issue 30)"
python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); c=[x for x in r["rows"] if x["check"]=="conformance"][0]
assert r["runs"]==3 and c["failed"]+c["internal_errors"]==3, c
named=sum(c["deviations"].values()); assert named==c["failed"], c
assert all(x.get("deviation") for x in c["counterexamples"]), c["counterexamples"]
assert r["internal_error_runs"]==c["internal_errors"] and len(r["internal_errors"])==min(1, c["internal_errors"]), r["internal_errors"]' "$dir/found.json" ||
  { cat "$dir/found.json"; fail "recorded run: not a named finding or an internal error on every theta"; }
ls "$dir"/found/*/finding.md > /dev/null 2>&1 || fail "recorded run: no finding saved"

# Shrinking: the program ignores its input, so no candidate keeps the finding; the
# audit must still end with its report and the finding as found.
"$lepp" audit --cmd "$cmd" --inputs "$rec/tri.poly" --theta 20 --compare none --max-findings 1 --shrink-seconds 20 \
  -j 2 --out "$dir/shrunk" --json > "$dir/shrunk.json"; s=$?
[ $s -eq 1 ] || [ $s -eq 3 ] || fail "recorded run, shrinking: exit $s"
python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); assert r["runs"]==1, r' "$dir/shrunk.json" ||
  fail "recorded run, shrinking: no report"

# Tolerances the replay cannot make exact are bad usage, not an internal error of every run.
"$lepp" audit --engine fast --sources gen --cases 1 --compare none --point-tolerance nan --out "$dir/nan" 2> "$dir/err" > /dev/null; s=$?
[ $s -eq 2 ] || fail "--point-tolerance nan: exit $s"
grep -q "must be finite" "$dir/err" || fail "--point-tolerance nan: $(cat "$dir/err")"
echo "OK"
