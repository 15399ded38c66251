#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Two lepp binaries, byte for byte the same certificates: `lepp certify`'s stdout, stderr
# and exit status, as text and --json, with --threads 1 and 2, and theta as refined, 45
# and 60 (the angle check's candidates from both of its paths), on meshes OLD refines:
# the paper's problems and the hostile corpus at 20 and 33 degrees, and a copy of each
# broken (a triangle turned clockwise, a triangle dropped: gaps, overlaps); the stored
# meshes at the limit of double precision (with --exempt-small-input-angles); and
# Square400 at --max-area 0.15 (about 10^5 triangles), certified with that bound, with
# 0.1 (area violations) and with 0.1 and --region-areas. A speed-up of the certifier
# must leave every byte as it was (issue 40 item 3).
# usage: bench/same_certificates.sh OLD_LEPP NEW_LEPP
# Prints the cases that differ and a summary; exits 1 when anything differs.
set -uo pipefail
cd "$(dirname "$0")/.."
old=$(readlink -f "$1")
new=$(readlink -f "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cases=()  # input|mesh prefix|theta|other options
for p in corpus/paper/*.poly corpus/hostile/*.poly; do
  for theta in 20 33; do
    m=$work/$(basename "$p" .poly)-$theta
    "$old" refine "$p" --min-angle "$theta" -q -o "$m" > /dev/null 2>&1 || continue
    cases+=("$p|$m|$theta|")
    # Broken: the first triangle clockwise, the third dropped (the header's count with it).
    awk 'NR == 1 { print $1 - 1, $2, $3; next } NR == 2 { print $1, $2, $4, $3; next } NR == 4 { next } { print }' \
      "$m.ele" > "$m-broken.ele"
    cp "$m.node" "$m-broken.node"
    cases+=("$p|$m-broken|$theta|")
  done
done
for mesh in corpus/regressions/precision/*/out.ele; do
  dir=$(dirname "$mesh")
  input=corpus/regressions/precision/$(basename "$dir" | sed 's/-[a-z]*-[0-9]*$//').poly
  [[ -f $input ]] && cases+=("$input|$dir/out|25|--exempt-small-input-angles")
done
square=$work/square400
"$old" refine corpus/paper/square400.poly --min-angle 30 --max-area 0.15 -q -o "$square" > /dev/null
cases+=("corpus/paper/square400.poly|$square|30|--max-area 0.15" "corpus/paper/square400.poly|$square|30|--max-area 0.1"
        "corpus/paper/square400.poly|$square|30|--max-area 0.1 --region-areas")

runs=0
differ=0
declare -A status
for c in "${cases[@]}"; do
  IFS='|' read -r input prefix theta options <<< "$c"
  for angle in "$theta" 45 60; do
    for json in "" --json; do
      for threads in 1 2; do
        # shellcheck disable=SC2086  # options are words
        a=$("$old" certify "$input" "$prefix" --min-angle "$angle" $options $json --threads "$threads" 2>&1; echo "exit $?")
        # shellcheck disable=SC2086
        b=$("$new" certify "$input" "$prefix" --min-angle "$angle" $options $json --threads "$threads" 2>&1; echo "exit $?")
        runs=$((runs + 1))
        status[${a##*exit }]=$((${status[${a##*exit }]:-0} + 1))
        if [[ $a != "$b" ]]; then
          differ=$((differ + 1))
          echo "differ: certify $input $prefix --min-angle $angle $options $json --threads $threads"
        fi
      done
    done
  done
done
summary="$runs reports compared, $differ differ (exit status of OLD:"
for s in "${!status[@]}"; do summary+=" $s: ${status[$s]}"; done
echo "$summary)"
[[ $differ -eq 0 ]]
