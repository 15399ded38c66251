#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Issue 28's check of lepp against its own strict certificate: every .poly and .node
# input of corpus/ that lepp reads (meshes stored beside findings and the parser's
# seeds excluded), by the centroid method at 10 to 30 degrees and by the midpoint
# method at 10 to 22, in both engines: the meshes must be identical and certify
# under the strict rule (lepp certify --exempt-small-input-angles, no ties option;
# a guard stop is certified without the angle, as a valid mesh). Prints one line per
# run that fails and a summary table on stdout, progress on stderr.
# usage: bench/corpus_certify_sweep.sh [LEPP]   (SKIP, a regex, skips neardup30k: bench/precision_sweep.sh; reference-slow-cluster: minutes)
set -uo pipefail
cd "$(dirname "$0")/.."
lepp=$(readlink -f "${1:-build/cli/lepp}")
skip=${SKIP:-neardup30k|reference-slow}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
inputs=$(find corpus/paper corpus/hostile corpus/triangle-formats corpus/regressions/precision corpus/audits \
  -maxdepth 3 \( -name '*.poly' -o -name '*.node' \) | grep -v -E '/(out|mesh)\.(node|poly)$' | sort)
runs=0 certified=0 differ=0 failed=0 unread=0
for input in $inputs; do
  [[ -n $skip && $input =~ $skip ]] && continue
  # a .node beside a .poly of the same name is the .poly's vertex file, not an input
  [[ $input == *.node && -f ${input%.node}.poly ]] && continue
  "$lepp" refine "$input" -o "$work/probe" --max-steiner 0 -q > /dev/null 2>&1
  [[ $? == 2 ]] && { unread=$((unread + 1)); continue; }
  for spec in centroid:10 centroid:15 centroid:20 centroid:25 centroid:30 midpoint:10 midpoint:15 midpoint:20 midpoint:22; do
    method=${spec%%:*} theta=${spec##*:}
    echo "corpus sweep: $input $method $theta" >&2
    for engine in fast reference; do
      "$lepp" refine "$input" -o "$work/$engine" --method "$method" --min-angle "$theta" --engine "$engine" --json -q \
        > "$work/$engine.json" 2> /dev/null
    done
    runs=$((runs + 1))
    if ! cmp -s "$work/fast.node" "$work/reference.node" || ! cmp -s "$work/fast.ele" "$work/reference.ele"; then
      differ=$((differ + 1)); echo "- $input $method $theta: the engines' meshes differ"; continue
    fi
    outcome=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['outcome'])" "$work/fast.json" 2>/dev/null)
    angle=$theta
    [[ $outcome == converged || $outcome == unimprovable ]] || angle=0
    if "$lepp" certify "$input" "$work/fast" --method "$method" --min-angle "$angle" --exempt-small-input-angles \
        > "$work/cert" 2>&1; then
      certified=$((certified + 1))
    else
      failed=$((failed + 1)); echo "- $input $method $theta ($outcome): $(grep -m1 -E '^[a-z]+(-[a-z0-9]+)+: ' "$work/cert")"
    fi
  done
done
echo
echo "| runs | identical meshes | certified (strict) | not certified | inputs not read (exit 2) |"
echo "|---:|---:|---:|---:|---:|"
echo "| $runs | $((runs - differ)) | $certified | $failed | $unread |"
