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
# refused NAME MESSAGE: the catalogue in $scratch/NAME.txt (on stdin) must fail the check
# naming MESSAGE.
refused() {
  cat > "$scratch/$1.txt"
  out=$("$python" "$src/tools/mutation/run.py" --check --catalogue "$scratch/$1.txt")
  code=$?
  echo "$out"
  if [ "$code" -ne 1 ] || ! echo "$out" | grep -q "$2"; then
    echo "FAIL: $1 was not refused with \"$2\" (exit $code)"; exit 1
  fi
}
refused twice "mutant matches-twice: 'from' occurs" <<'CAT'
[matches-twice]
file = tools/mutation/run.py
from = import
to = export
bug = none: an edit whose text occurs many times
CAT
refused untested "mutant no-quick-tests: no 'quick' or no 'targets'" <<'CAT'
[no-quick-tests]
file = tools/mutation/run.py
from = def parse_catalogue(path):
to = def parse_catalogue(path, unused=None):
bug = none: an entry that lost its quick and targets lines
CAT
echo "ok: the catalogue applies, and a stale one or one without quick tests is refused"
