#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# What `lepp` loads at start (issue 40, item 4): the fuzzers and the audit start
# `lepp refine` once per input, so only `lepp theorems` may load Z3 (libz3: 23 MB,
# some 24,000 relocations) and MPFI; it runs them in its helper, lepp-theorems
# (cli/helper.h). The dynamic loader's own list (LD_DEBUG=libs: every object it
# maps, "calling init: PATH") of `lepp --version`, a tiny `lepp refine --trace` and
# `lepp certify` has neither; `lepp theorems --prove` (the positive control: the
# check sees libz3 when it is there) has both and proves its row. Without the
# helper beside it, `lepp theorems` is exit 1 naming the helper, and its help and
# `lepp --help` are unchanged. Linux (glibc's loader) only.
# usage: startup_libraries_test.sh LEPP_BINARY
set -u
lepp=$1
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# loaded NAME WANT_EXIT ARGS...: runs lepp ARGS under LD_DEBUG=libs; the objects it loaded
# (every process of the run: the helper's exec too) go to $dir/NAME.libs.
loaded() {
  local name=$1 want=$2; shift 2
  local s=0
  LD_DEBUG=libs LD_DEBUG_OUTPUT="$dir/$name.ld" "$lepp" "$@" > "$dir/$name.out" 2> "$dir/$name.err" || s=$?
  [ "$s" -eq "$want" ] || { cat "$dir/$name.err"; fail "$name: exit $s, expected $want"; }
  cat "$dir/$name.ld".* 2>/dev/null | sed -n 's/.*calling init: //p' | sort -u > "$dir/$name.libs"
  [ -s "$dir/$name.libs" ] || fail "$name: LD_DEBUG=libs listed nothing (not glibc's loader?)"
}

printf '4 2 0 0\n1 0 0\n2 4 0\n3 4 3\n4 0 3\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n' > "$dir/in.poly"
loaded version 0 --version
loaded refine 0 refine "$dir/in.poly" -o "$dir/out" --min-angle 25 --method centroid --trace -q
loaded certify 0 certify "$dir/in.poly" "$dir/out" --min-angle 25
for name in version refine certify; do
  if grep -E '/lib(z3|mpfi)\.so' "$dir/$name.libs"; then
    fail "lepp $name loads Z3 or MPFI at start (above): only lepp theorems needs them"
  fi
  echo "ok: lepp $name loads $(wc -l < "$dir/$name.libs") objects, neither libz3 nor libmpfi"
done

row=Lemma7.AcuteAlpha1AtLeast079Alpha0  # its proof uses both MPFI and Z3, in 0.2 s
loaded theorems 0 theorems --prove --only $row
grep -q '/libz3\.so' "$dir/theorems.libs" && grep -q '/libmpfi\.so' "$dir/theorems.libs" ||
  { cat "$dir/theorems.libs"; fail "lepp theorems --prove loaded no libz3 or no libmpfi: the check above cannot see them"; }
grep -q "\`$row\`.*\*\*proved\*\*" "$dir/theorems.out" || { cat "$dir/theorems.out" "$dir/theorems.err"; fail "theorems: $row not proved"; }
echo "ok: lepp theorems --prove loads libz3 and libmpfi (in lepp-theorems) and proves $row"

# Without its helper (lepp alone in a directory): help as before, the run a broken install.
mkdir "$dir/alone"
cp "$lepp" "$dir/alone/lepp"
"$dir/alone/lepp" --help > "$dir/help.out" 2>&1 || fail "lepp --help without the helper: exit $?"
grep -q '^ *theorems ' "$dir/help.out" || { cat "$dir/help.out"; fail "lepp --help does not list theorems"; }
"$dir/alone/lepp" theorems --help > "$dir/theorems-help.out" 2>&1 || fail "lepp theorems --help without the helper: exit $?"
grep -q -- '--prove' "$dir/theorems-help.out" || { cat "$dir/theorems-help.out"; fail "lepp theorems --help lists no --prove"; }
s=0
"$dir/alone/lepp" theorems --only $row > "$dir/alone.out" 2> "$dir/alone.err" || s=$?
[ "$s" -eq 1 ] || fail "lepp theorems without its helper: exit $s, expected 1 (a broken install)"
grep -q 'lepp-theorems is missing' "$dir/alone.err" || { cat "$dir/alone.err"; fail "the message does not name lepp-theorems"; }
[ ! -s "$dir/alone.out" ] || fail "lepp theorems without its helper wrote to stdout"
echo "ok: without lepp-theorems: help unchanged, lepp theorems exit 1: $(cat "$dir/alone.err")"
