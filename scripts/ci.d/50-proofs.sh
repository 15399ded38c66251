#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The proof obligations of `lepp theorems --prove` (corpus/theorems/proofs/, each
# file's answer in expected.txt) re-checked by two independent programs: Debian's
# z3 binary on the SMT-LIB 2 files and QEPCAD B (cylindrical algebraic
# decomposition) on its input files, each with a time limit. Fails unless every
# answer is the recorded one, so where both files exist the two procedures agree
# (unsat = TRUE: the statement holds; sat = FALSE: it does not).
set -euo pipefail
cd "$(dirname "$0")/../.."
dir=corpus/theorems/proofs
limit=${LEPP_PROOF_TIME_LIMIT:-120}
failed=0
while read -r file expected; do
  case "$file" in ''|'#'*) continue ;; esac
  case "$file" in
    *.smt2) got=$(timeout "$limit" z3 "$dir/$file" 2>&1 | paste -sd, - || true) ;;
    *.qepcad)
      got=$(timeout "$limit" qepcad +N200000000 < "$dir/$file" 2>&1 |
        awk '/An equivalent quantifier-free formula:/ { getline; getline; print; exit }' || true) ;;
    *) echo "proofs: unknown kind of file $file" >&2; exit 2 ;;
  esac
  got=${got:-no answer within ${limit} s}
  if [ "$got" = "$expected" ]; then
    echo "proofs: $file $got"
  else
    echo "proofs: $file: expected $expected, got $got" >&2
    failed=1
  fi
done < "$dir/expected.txt"
# Where a row has both files, the two answers must say the same (checked above
# against expected.txt, which the library writes consistently: unsat with TRUE).
while read -r file expected; do
  case "$file" in *.qepcad) ;; *) continue ;; esac
  smt=${file%.qepcad}.smt2
  want=$([ "$expected" = TRUE ] && echo unsat || echo sat)
  if grep -q "^$smt " "$dir/expected.txt" && ! grep -Eq "^$smt $want(,$want)*\$" "$dir/expected.txt"; then
    echo "proofs: $smt and $file disagree in expected.txt" >&2
    failed=1
  fi
done < "$dir/expected.txt"
exit $failed
