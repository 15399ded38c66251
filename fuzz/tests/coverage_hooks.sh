#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The fuzz build's coverage instrumentation at work in a linked fuzz target
# (LEPP_FUZZ_INSTRUMENT in the top-level CMakeLists.txt): no call to libFuzzer's
# comparison hooks (__sanitizer_cov_trace_*cmp*) anywhere (-fno-sanitize-coverage=
# trace-cmp: docs/FUZZING.md "Throughput"); edge counters (increments of the
# __sancov_cntrs section) in lepp's own functions, and none in a function of CGAL,
# boost, the standard library, gmpxx, fmt or nlohmann-json (fuzz/coverage-ignorelist.txt).
# Functions by mangled name.
# usage: fuzz/tests/coverage_hooks.sh OBJDUMP BINARY
set -euo pipefail
objdump=$1 binary=$2
# The counters' section: its start and size, in hex.
read -r start size < <("$objdump" -h "$binary" | awk '$2 == "__sancov_cntrs" { print $4, $3 }')
[[ -n ${start:-} ]] || { echo "coverage_hooks: $binary has no __sancov_cntrs section (no edge counters)" >&2; exit 1; }
"$objdump" -d --no-show-raw-insn "$binary" | awk -v start="$((16#$start))" -v size="$((16#$size))" '
  function third_party(f) {
    return f ~ /^_Z(N|NK|NR|NKR|ZN|ZNK)?(4CGAL|4CORE|5boost|St|9__gnu_cxx|10__gmp_expr|1[78]__gmp_binary_|3fmt|8nlohmann)/ ||
           f ~ /^_ZSt/ || f ~ /^_ZThn.*_N5boost/
  }
  function hex(s,   i, c, v) {
    v = 0
    for (i = 1; i <= length(s); ++i) { c = index("0123456789abcdef", substr(s, i, 1)); v = v * 16 + c - 1 }
    return v
  }
  /^[0-9a-f]+ </ { fn = substr($2, 2); sub(/>:$/, "", fn); next }
  /call.*<__sanitizer_cov_trace_(const_)?cmp/ { hooks++; if (hooks <= 3) print "comparison hook in " fn; next }
  /addb +\$0x1,.*\(%rip\) +# [0-9a-f]+ / {
    match($0, /# [0-9a-f]+ /)
    at = hex(substr($0, RSTART + 2, RLENGTH - 3))
    if (at < start || at >= start + size) next
    if (third_party(fn)) { third++; if (third <= 3) print "edge counter in third-party function " fn }
    else if (fn ~ /^_Z+N?K?4lepp/) lepp++
  }
  END {
    printf "comparison hooks: %d; edge counters: %d in third-party functions, %d in lepp'"'"'s\n", hooks, third, lepp
    exit (hooks > 0 || third > 0 || lepp == 0) ? 1 : 0
  }'
