#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# lepp refine's output errors reach the user (issue 42): with one output thread and with
# two (--threads 2 writes the .node on a second thread beside the .ele and .poly), each
# file it writes made unwritable in turn (a directory in the way; /dev/full, where the
# error shows only when the buffer is written or closed) ends the run with exit 2 and
# one line on stderr naming that file, never a success with a file missing, an
# internal error (exit 1) or an abort. The same run into a writable prefix is exit 0
# (or 3 where it leaves unimprovable triangles), so each failure is the file's doing.
# usage: write_errors_test.sh LEPP_BINARY SOURCE_DIR
set -u
lepp=$1; src=$2
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
status=0
fail() { echo "FAIL: $*"; status=1; }

A=$src/corpus/paper/A.poly
# A 10-degree corner between two segments: lepp leaves its wedge triangle (exit 3, PREFIX.unimprovable).
corner=$src/audit/tests/mesher/inputs/small-angle-corner.poly

# expect NAME WANT_EXIT FILE_NAMED ARGS...: the run's exit status, and stderr one line naming FILE_NAMED.
expect() {
  local name=$1 want=$2 named=$3; shift 3
  "$lepp" refine "$@" > "$dir/$name.out" 2> "$dir/$name.err"; local s=$?
  if [ "$s" -ne "$want" ]; then fail "$name: exit $s, expected $want"; cat "$dir/$name.err"; return; fi
  [ -z "$named" ] && { echo "ok: $name (exit $s)"; return; }
  local lines; lines=$(wc -l < "$dir/$name.err")
  [ "$lines" -eq 1 ] || { fail "$name: $lines lines on stderr, expected one"; cat "$dir/$name.err"; return; }
  grep -qF -- "$named" "$dir/$name.err" || { fail "$name: stderr does not name $named"; cat "$dir/$name.err"; return; }
  echo "ok: $name (exit $s): $(cat "$dir/$name.err")"
}

for threads in 1 2; do
  # The premise: into a writable prefix the runs succeed and write every file.
  p=$dir/ok-$threads
  expect "ok-threads$threads" 0 "" "$A" -o "$p" --min-angle 25 --trace -q --threads "$threads"
  for ext in node ele poly trace; do [ -s "$p.$ext" ] || fail "ok-threads$threads: $p.$ext missing or empty"; done
  expect "ok-corner-threads$threads" 3 "" "$corner" -o "$dir/okc-$threads" --min-angle 25 -q --threads "$threads"
  [ -s "$dir/okc-$threads.unimprovable" ] || fail "the corner left no unimprovable triangle: the .unimprovable cases test nothing"

  for ext in node ele poly trace; do
    # A directory where the file goes: the open fails.
    p=$dir/dir-$threads-$ext
    mkdir "$p.$ext"
    expect "directory-$ext-threads$threads" 2 "$p.$ext" "$A" -o "$p" --min-angle 25 --trace -q --threads "$threads"
    # /dev/full: the open succeeds, the write or the close fails (ENOSPC).
    p=$dir/full-$threads-$ext
    ln -s /dev/full "$p.$ext"
    expect "full-disk-$ext-threads$threads" 2 "$p.$ext" "$A" -o "$p" --min-angle 25 --trace -q --threads "$threads"
  done
  p=$dir/dir-$threads-unimprovable; mkdir "$p.unimprovable"
  expect "directory-unimprovable-threads$threads" 2 "$p.unimprovable" "$corner" -o "$p" --min-angle 25 -q --threads "$threads"
  p=$dir/full-$threads-unimprovable; ln -s /dev/full "$p.unimprovable"
  expect "full-disk-unimprovable-threads$threads" 2 "$p.unimprovable" "$corner" -o "$p" --min-angle 25 -q --threads "$threads"
  # The other formats (written on the main thread).
  for fmt in vtu msh4; do
    ext=$fmt; [ "$fmt" = msh4 ] && ext=msh
    p=$dir/dir-$threads-$fmt; mkdir "$p.$ext"
    expect "directory-$fmt-threads$threads" 2 "$p.$ext" "$A" -o "$p" --min-angle 25 -q --threads "$threads" --format "$fmt"
    p=$dir/full-$threads-$fmt; ln -s /dev/full "$p.$ext"
    expect "full-disk-$fmt-threads$threads" 2 "$p.$ext" "$A" -o "$p" --min-angle 25 -q --threads "$threads" --format "$fmt"
  done
  # A folder that does not exist: every file fails, one message.
  expect "no-folder-threads$threads" 2 "$dir/none/mesh" "$A" -o "$dir/none/mesh" --min-angle 25 -q --threads "$threads"
done
[ "$status" -eq 0 ] && echo "ok: every output error reaches the user"
exit "$status"
