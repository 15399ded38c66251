#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The fuzz build's coverage ignorelist (fuzz/coverage-ignorelist.txt) at work in a
# linked fuzz target: no call to libFuzzer's comparison hooks
# (__sanitizer_cov_trace_*cmp*) from a function of CGAL, boost, the standard
# library, gmpxx, fmt or nlohmann-json, and some from lepp's own functions (the
# fuzzer's guidance over lepp's code stays). Functions by mangled name.
# usage: fuzz/tests/coverage_hooks.sh OBJDUMP BINARY
set -euo pipefail
objdump=$1 binary=$2
"$objdump" -d --no-show-raw-insn "$binary" | awk '
  /^[0-9a-f]+ </ { fn = substr($2, 2); sub(/>:$/, "", fn); next }
  /call.*<__sanitizer_cov_trace_(const_)?cmp/ {
    if (fn ~ /^_Z(N|NK|NR|NKR|ZN|ZNK)?(4CGAL|4CORE|5boost|St|9__gnu_cxx|10__gmp_expr|1[78]__gmp_binary_|3fmt|8nlohmann)/ ||
        fn ~ /^_ZSt/ || fn ~ /^_ZThn.*_N5boost/) { third++; if (third <= 3) print "hooked third-party function: " fn }
    else if (fn ~ /^_Z+N?K?4lepp/) lepp++
  }
  END {
    printf "comparison hooks: %d in third-party functions, %d in lepp'"'"'s\n", third, lepp
    exit (third > 0 || lepp == 0) ? 1 : 0
  }'
