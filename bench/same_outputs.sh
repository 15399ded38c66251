#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Two lepp binaries, byte for byte the same outputs: every file `lepp refine` writes
# (.node/.ele/.poly/.unimprovable, .vtu, ASCII .msh of formats 2.2 and 4.1) and what it
# prints (the text statistics and --json, without the seconds the clock writes),
# on the paper's four problems at several angles, with and without a size bound, on the
# hostile corpus (coordinates near 1e300, 1e-300, subnormal) at 20 and 30 degrees, on
# Square400 at --max-area 0.015 (about 10^6 triangles), and on the inputs at the limit
# of double precision (corpus/regressions/precision) at 25 and 30 degrees.
# A speed-up of the writers or the statistics must leave every byte as it was.
# usage: bench/same_outputs.sh OLD_LEPP NEW_LEPP [THETAS]   (default "20 25 28 30 33")
# environment: ORDERS="fifo lifo flip random smallest-angle batch" runs every case in
#   each of these --order (default: fifo, the default order, alone); fifo and batch
#   with --threads 1 and 2 (the mesh is the same for every number; fifo's second
#   thread makes the .node's lines beside the refinement).
# Prints one line per run and a summary; exits 1 when anything differs.
set -uo pipefail
cd "$(dirname "$0")/.."
old=$(readlink -f "$1")
new=$(readlink -f "$2")
thetas=${3:-20 25 28 30 33}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
runs=0
differ=0

# One case: both binaries, text and --json, then every output file compared.
compare() {  # label input [refine options...]
  local label="$1$tag" input=$2
  shift 2
  local side rc_old rc_new
  for side in old new; do
    # The same output prefix for both: the text and the JSON name it.
    mkdir -p "$work/run"
    local bin=$old
    [[ $side == new ]] && bin=$new
    "$bin" refine "$input" -o "$work/run/m" -q --format triangle,vtu,msh2 "$@" ${extra[@]:+"${extra[@]}"} 2> "$work/run/err" |
      grep -v '^seconds' > "$work/run/text"
    echo "${PIPESTATUS[0]}" > "$work/run/rc"
    "$bin" refine "$input" -o "$work/run/j" -q --json --format msh4 "$@" ${extra[@]:+"${extra[@]}"} 2> /dev/null |
      grep -v -E '"seconds"|^    "(cdt|read|refine|statistics|write)": ' > "$work/run/json"
    mv "$work/run" "$work/$side"
  done
  runs=$((runs + 1))
  local files
  files=$(cd "$work/old" && ls)
  if [[ "$files" != "$(cd "$work/new" && ls)" ]]; then
    echo "DIFFER $label: the files written differ ($(cd "$work/new" && ls | tr '\n' ' '))"
    differ=$((differ + 1))
  else
    local f bad=""
    for f in $files; do cmp -s "$work/old/$f" "$work/new/$f" || bad="$bad $f"; done
    if [[ -n $bad ]]; then
      echo "DIFFER $label:$bad"
      differ=$((differ + 1))
    else
      echo "same   $label ($(cat "$work/old/rc"), $(cat "$work"/old/[mj].* 2> /dev/null | wc -c) bytes of mesh files)"
    fi
  fi
  rm -rf "$work/old" "$work/new"
}

cases() {
for theta in $thetas; do
  for p in A square400 circles240 rect162; do
    compare "$p $theta" "corpus/paper/$p.poly" --min-angle "$theta"
  done
  compare "square400 $theta a=0.15" corpus/paper/square400.poly --min-angle "$theta" --max-area 0.15
done
# The benchmark's problem: about 10^6 triangles, every histogram-like decision many times over.
compare "square400 30 a=0.015" corpus/paper/square400.poly --min-angle 30 --max-area 0.015
for theta in 20 30; do
  for f in corpus/hostile/*.poly; do
    compare "$(basename "$f" .poly) $theta" "$f" --min-angle "$theta" --max-steiner 20000
  done
done
# At the limit of double precision: precision stops and triangles left (ALGORITHM.md 8b).
for theta in 25 30; do
  for f in corpus/regressions/precision/*.node corpus/regressions/precision/*.poly; do
    compare "$(basename "$f") $theta" "$f" --min-angle "$theta" --max-steiner 20000
  done
done
}

# Each case in each order asked for: the default order alone unless ORDERS says.
extra=()
tag=""
if [[ -z ${ORDERS:-} ]]; then
  cases
else
  for order in $ORDERS; do
    order_args=(--order "$order")
    [[ $order == random ]] && order_args+=(--order-seed 7)
    thread_counts=1
    [[ $order == batch || $order == fifo ]] && thread_counts="1 2"
    for threads in $thread_counts; do
      extra=("${order_args[@]}" --threads "$threads")
      tag=" [$order, $threads thread(s)]"
      cases
    done
  done
fi
echo "$runs cases, $differ differ"
[[ $differ == 0 ]]
