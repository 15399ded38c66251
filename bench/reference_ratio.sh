#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The reference engine against the fast one on the precision corpus (issue 40, item 4:
# within 10x): every .poly and .node of corpus/regressions/precision refined by both
# engines (centroid) at each theta, CPU seconds (user + system) of the whole process,
# and their ratio where the fast engine takes at least 0.05 s (below that the process's
# start-up is the measure). Prints a markdown table, the largest ratio last.
# usage: bench/reference_ratio.sh [LEPP] [THETAS]   (default build/cli/lepp, "20 30")
set -euo pipefail
cd "$(dirname "$0")/.."
lepp=$(readlink -f "${1:-build/cli/lepp}")
thetas=${2:-20 30}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cpu() {  # ENGINE INPUT THETA: CPU seconds, or "timeout"
  local status=0
  /usr/bin/time -o "$work/time" -f '%U %S' timeout 600 "$lepp" refine "$2" -o "$work/out" --min-angle "$3" \
    --engine "$1" -q > /dev/null 2> "$work/err" || status=$?
  if [[ $status == 124 ]]; then echo timeout; return; fi
  awk 'END { printf "%.2f\n", $1 + $2 }' "$work/time"
}

echo "| input | θ | fast CPU s | reference CPU s | reference / fast |"
echo "|---|---:|---:|---:|---:|"
worst=0
for input in corpus/regressions/precision/*.poly corpus/regressions/precision/*.node; do
  for theta in $thetas; do
    fast=$(cpu fast "$input" "$theta")
    ref=$(cpu reference "$input" "$theta")
    ratio=$(awk -v f="$fast" -v r="$ref" 'BEGIN { if (r == "timeout") print "timeout"; else if (f >= 0.05) printf "%.1f\n", r / f; else print "-" }')
    echo "| $(basename "$input") | $theta | $fast | $ref | $ratio |"
    [[ $ratio != - && $ratio != timeout ]] && worst=$(awk -v a="$worst" -v b="$ratio" 'BEGIN { print (b > a) ? b : a }')
    [[ $ratio == timeout ]] && worst=timeout
  done
done
echo
echo "largest reference / fast: $worst"
