#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# `lepp audit` exit statuses and outputs: 0 clean (lepp refine through --cmd),
# 1 findings (a crashing program, CGAL's mesher crashing in its child process),
# 2 bad usage; JSON and JUnit well-formed.
# usage: audit_cli_test.sh LEPP_BINARY SOURCE_DIR
set -u
lepp=$1; src=$2
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
common=(--theta 25 --sources gen --compare none --root "$src" --out "$dir/findings")

"$lepp" audit --cmd "$lepp refine {in} -o {out} --min-angle {theta} --method {method} -q" "${common[@]}" --cases 6 \
  --json --junit "$dir/junit.xml" > "$dir/report.json"; s=$?
[ $s -eq 0 ] || { cat "$dir/report.json"; fail "lepp refine through --cmd: exit $s"; }
python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); assert r["holds"] and len(r["rows"])==5 and r["runs"]==6 and r["lepp_version"], r' \
  "$dir/report.json" || fail "JSON report"
python3 -c 'import sys,xml.dom.minidom as m; d=m.parse(sys.argv[1]); assert len(d.getElementsByTagName("testcase"))==5' \
  "$dir/junit.xml" || fail "JUnit report"

"$lepp" audit --cmd "$src/properties/audit/tests/programs/crash.sh {in} {out}" "${common[@]}" --cases 2 \
  --junit "$dir/junit2.xml" > "$dir/report.md"; s=$?
[ $s -eq 1 ] || { cat "$dir/report.md"; fail "crashing program: exit $s"; }
grep -q '| 1 | certificate .*FAILED' "$dir/report.md" || { cat "$dir/report.md"; fail "certificate row not failed"; }
ls "$dir"/findings/certificate-*/reproduce.sh > /dev/null 2>&1 || fail "no finding saved"
python3 -c 'import sys,xml.dom.minidom as m; d=m.parse(sys.argv[1]); assert d.getElementsByTagName("failure")' \
  "$dir/junit2.xml" || fail "JUnit failure"

"$lepp" audit --cmd "$src/properties/audit/tests/programs/crash.sh {in} {out} {angle}" "${common[@]}" 2> "$dir/err"; s=$?
[ $s -eq 2 ] || fail "unknown placeholder: exit $s"
grep -q 'unknown placeholder {angle}' "$dir/err" || fail "message: $(cat "$dir/err")"
"$lepp" audit --cmd "/no/such/mesher {in} {out}" "${common[@]}" 2> "$dir/err"; s=$?
[ $s -eq 2 ] || fail "program not found: exit $s"
"$lepp" audit --engine fast --inputs "$dir/no-such-dir" "${common[@]}" 2> /dev/null; s=$?
[ $s -eq 2 ] || fail "missing --inputs directory: exit $s"

# CGAL's mesher segfaults on this input (Debian's CGAL): isolated in a child, that is
# one crashed run of the report (exit 1), not the end of the audit (exit 139).
"$lepp" audit --engine cgal --inputs "$src/properties/audit/tests/inputs/cgal-crash.poly" --theta 20 --timeout 5 \
  --compare none --no-shrink --root "$src" --out "$dir/cgal" --json > "$dir/cgal.json"; s=$?
[ $s -eq 1 ] || fail "CGAL crash: exit $s (the crash was not contained)"
python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); assert r["run_status"]["crashed"]==1, r["run_status"]; assert "killed by signal" in r["rows"][0]["first"], r["rows"][0]' \
  "$dir/cgal.json" || fail "CGAL crash: not reported as crashed (if CGAL no longer crashes here, pick another input)"
echo "OK"
