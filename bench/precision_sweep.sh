#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Issue 20's two inputs at the limit of double precision (corpus/regressions/precision:
# cluster34.node, neardup30k.node) in both engines at every integer theta from 10 to 33
# degrees, each mesh certified with the precision-limit exemption (docs/CERTIFIER.md
# section 5c, which reads only the input and the mesh). Writes the markdown table of
# docs/ALGORITHM.md section 8b to stdout, progress to stderr.
# A point set always meshes its convex hull, so --convex-hull gives the same domain:
# the fast engine is run with it too and its mesh compared byte for byte.
# usage: bench/precision_sweep.sh [LEPP] [THETAS]   (default build/cli/lepp, "10 11 ... 33";
#        FILES="cluster34 neardup30k" picks the inputs). Run it under nice -n 10.
set -uo pipefail
cd "$(dirname "$0")/.."
lepp=$(readlink -f "${1:-build/cli/lepp}")
thetas=${2:-$(seq -s ' ' 10 33)}
files=${FILES:-cluster34 neardup30k}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# One row: refine (exit, points, left at double precision, seconds), then certify.
row() {  # input theta engine label [refine options...]
  local input=$1 theta=$2 engine=$3 label=$4
  shift 4
  local out="$work/$label"
  "$lepp" refine "corpus/regressions/precision/$input.node" -o "$out" --min-angle "$theta" --engine "$engine" \
    --json -q "$@" > "$out.json" 2> "$out.err"
  local rc=$?
  local verdict
  if [[ $rc == 0 || $rc == 3 ]]; then
    "$lepp" certify "corpus/regressions/precision/$input.node" "$out" --min-angle "$theta" --exempt-precision-limited \
      --json "$@" > "$out.cert.json" 2> "$out.cert.err"
    # Not certified: again with lepp's own tie rule (--precision-ties-by-ids, CERTIFIER.md 5c, Finding).
    "$lepp" certify "corpus/regressions/precision/$input.node" "$out" --min-angle "$theta" --exempt-precision-limited \
      --precision-ties-by-ids --json "$@" > "$out.ids.json" 2> /dev/null
    verdict=$(python3 - "$out.cert.json" "$out.ids.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
if r["certified"]:
    print(f"certified ({r['precision_exempt_count']} exempt)")
else:
    ids = json.load(open(sys.argv[2]))
    print("**not certified**: " + ", ".join(f"{n} {k}" for k, n in r["violation_counts"].items() if n) +
          ("; certified with lepp's tie rule" if ids["certified"] else "; not with lepp's tie rule either"))
PY
)
  else
    verdict="**exit $rc**: $(head -c 200 "$out.err")"
  fi
  python3 - "$out.json" "$input" "$theta" "$label" "$rc" "$verdict" <<'PY'
import json, sys
path, input_, theta, label, rc, verdict = sys.argv[1:]
try:
    r = json.load(open(path))
    print(f"| {input_} | {theta} | {label} | {rc} | {r['outcome']} | {r['steiner_points']} | "
          f"{r['unimprovable_by_reason']['double-precision']} | {r['precision_stops']} | {verdict} | {r['seconds']:.2f} |")
except (OSError, ValueError, KeyError):
    print(f"| {input_} | {theta} | {label} | {rc} | | | | | {verdict} | |")
PY
}

same() {  # a b: byte-identical meshes?
  cmp -s "$work/$1.node" "$work/$2.node" && cmp -s "$work/$1.ele" "$work/$2.ele" && cmp -s "$work/$1.unimprovable" "$work/$2.unimprovable"
}

echo "| input | theta | engine | exit | outcome | points added | left at double precision | precision stops | certify --exempt-precision-limited | seconds |"
echo "|---|---:|---|---:|---|---:|---:|---:|---|---:|"
differ=()
for input in $files; do
  for theta in $thetas; do
    echo "precision sweep: $input at $theta" >&2
    row "$input" "$theta" fast fast
    row "$input" "$theta" reference reference
    "$lepp" refine "corpus/regressions/precision/$input.node" -o "$work/hull" --min-angle "$theta" --convex-hull -q \
      > /dev/null 2>&1
    same fast reference || differ+=("$input at $theta: fast and reference differ")
    same fast hull || differ+=("$input at $theta: --convex-hull differs")
  done
done
echo
if ((${#differ[@]})); then
  printf -- '- **%s**\n' "${differ[@]}"
else
  echo "At every row both engines write the same mesh (.node, .ele, .unimprovable byte for byte), and"
  echo "the fast engine with --convex-hull the same as without."
fi
