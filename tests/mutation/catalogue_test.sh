#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The mutation catalogue still applies to the tree: every mutant's 'from' text
# occurs exactly once in its file (tools/mutation/run.py --check). Code edited
# since a mutant was written makes it stale long before the opt-in run notices.
# And the check can fail: a catalogue whose edit matches twice is refused, and so is
# an entry with no quick tests (not argued equivalent): the quick pass would run nothing.
# usage: catalogue_test.sh PYTHON SOURCE_DIR SCRATCH_DIR
set -u
python=$1 src=$2 scratch=$3
mkdir -p "$scratch"
"$python" "$src/tools/mutation/run.py" --check || { echo "FAIL: the catalogue does not apply"; exit 1; }
cat > "$scratch/twice.txt" <<'CAT'
[matches-twice]
file = tools/mutation/run.py
from = import
to = export
bug = none: an edit whose text occurs many times
CAT
out=$("$python" "$src/tools/mutation/run.py" --check --catalogue "$scratch/twice.txt")
code=$?
echo "$out"
if [ "$code" -ne 1 ] || ! echo "$out" | grep -q "mutant matches-twice: 'from' occurs"; then
  echo "FAIL: a mutant whose 'from' occurs many times was not refused (exit $code)"; exit 1
fi
cat > "$scratch/untested.txt" <<'CAT'
[no-quick-tests]
file = tools/mutation/run.py
from = def parse_catalogue(path):
to = def parse_catalogue(path, unused=None):
bug = none: an entry that lost its quick and targets lines
CAT
out=$("$python" "$src/tools/mutation/run.py" --check --catalogue "$scratch/untested.txt")
code=$?
echo "$out"
if [ "$code" -ne 1 ] || ! echo "$out" | grep -q "mutant no-quick-tests: no 'quick' or no 'targets'"; then
  echo "FAIL: a mutant without quick tests was not refused (exit $code)"; exit 1
fi
echo "ok: the catalogue applies, and a stale one or one without quick tests is refused"
