#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Compares what two builds of lepp print and write, timings aside: the check that a
# restructuring changed no behaviour (issue 29). Runs every subcommand on the paper's
# problems, the corpus's inputs (bad ones included), and the audit's built-in sources,
# with both builds, and diffs stdout, stderr, exit status and every file written.
#   tools/restructure/compare_outputs.sh OLD_LEPP NEW_LEPP [WORK]
# Exit 0 when everything is identical; else the differing cases are listed (diff -r WORK/old WORK/new).
# QUICK=1 runs a smaller set (the paper's problems at one angle, a few corpus files).
set -uo pipefail
[[ $# -ge 2 ]] || { echo "usage: $0 OLD_LEPP NEW_LEPP [WORK]" >&2; exit 2; }
old=$(realpath "$1") new=$(realpath "$2")
work=${3:-out/compare-outputs}
root=$(cd "$(dirname "$0")/../.." && pwd)
rm -rf "$work" && mkdir -p "$work/old" "$work/new"
work=$(realpath "$work")

# Timings, the version's commit, paths of the two work folders, the program's own path
# (help's Usage line), the source tree a build finds its corpus in, and RapidCheck's own
# seed of an unseeded run (`lepp theorems` prints it) are masked.
masks=(-e "s#$work/(old|new)#WORK#g"
  -e 's/("[a-z_]*(seconds|_s|_ms|time)[a-z_]*"[[:space:]]*:[[:space:]]*)[0-9.eE+-]+/\1T/g'
  -e 's/("(read|cdt|refine|write|statistics)"[[:space:]]*:[[:space:]]*)[0-9.eE+-]+/\1T/g'
  -e 's/[0-9]+(\.[0-9]+)?( ?)(s|ms|seconds)\b/T\2\3/g'
  -e 's/(commit|git)[ :]+[0-9a-f]{7,40}(-dirty)?/\1 C/g'
  -e 's/time="[0-9.]+"/time="T"/g'
  -e 's/^((seconds|time)[[:space:]]+)[0-9.]+/\1T/'
  -e 's/^Usage: [^ ]+/Usage: lepp/'
  -e 's#/[^ "()]*/corpus/#ROOT/corpus/#g'
  -e 's/Using configuration: seed=[0-9]+/Using configuration: seed=S/')
mask() { sed -E "${masks[@]}"; }
# run NAME CMD...: runs CMD with {lepp} replaced by each build, in WORK/SIDE/NAME/.
n=0
run() {
  local name=$1; shift
  for side in old new; do
    local bin=$old; [[ $side == new ]] && bin=$new
    local dir=$work/$side/$name
    mkdir -p "$dir"
    local args=()
    for a in "$@"; do args+=("${a//\{lepp\}/$bin}"); done
    (cd "$dir" && "${args[@]}" > stdout.raw 2> stderr.raw; echo $? > status)
    for f in stdout stderr; do mask < "$dir/$f.raw" | sed "s#$bin#LEPP#g" > "$dir/$f"; rm "$dir/$f.raw"; done
    # files written: JSON and text masked in place, binary compared as is
    find "$dir" -type f \( -name '*.json' -o -name '*.md' -o -name '*.xml' -o -name '*.sh' -o -name '*.txt' \) -print0 |
      while IFS= read -r -d '' f; do sed -E -i "${masks[@]}" -e "s#$bin#LEPP#g" "$f"; done
  done
  n=$((n + 1))
}

paper=$root/corpus/paper
thetas="20 30"; [[ ${QUICK:-0} == 1 ]] && thetas=25
run help {lepp} --help-all
for p in "$paper"/*.poly; do
  k=$(basename "$p" .poly)
  for e in fast reference; do
    for m in centroid midpoint; do
      for t in $thetas; do
        [[ $m == midpoint && $t == 30 ]] && t=22
        run "refine-$k-$e-$m-$t" {lepp} refine "$p" -o mesh --engine "$e" --method "$m" --min-angle "$t" --max-steiner 200000 --json
        run "certify-$k-$e-$m-$t" sh -c "'{lepp}' refine '$p' -o mesh --engine $e --method $m --min-angle $t -q && '{lepp}' certify '$p' mesh --min-angle $t --exempt-small-input-angles --json && '{lepp}' certify '$p' mesh --min-angle $t --exempt-small-input-angles"
      done
    done
  done
  run "batch-$k" {lepp} refine "$p" -o mesh --order batch --threads 2 --min-angle 25 --json
  run "render-$k" sh -c "'{lepp}' refine '$p' -o mesh --min-angle 25 -q && '{lepp}' render mesh -o mesh.svg"
  run "trace-$k" {lepp} refine "$p" -o mesh --min-angle 25 --trace --format vtk
done

# The corpus: every .poly and .node lepp reads (the fuzzers' binary inputs aside), refined
# and certified by both engines; bad inputs give their messages.
i=0
while IFS= read -r f; do
  i=$((i + 1))
  [[ ${QUICK:-0} == 1 && $((i % 10)) != 0 ]] && continue
  k=$(echo "${f#"$root"/corpus/}" | tr '/' '_')
  run "corpus-$k" sh -c "for e in fast reference; do '{lepp}' refine '$f' -o mesh-\$e --engine \$e --min-angle 20 --json; echo \"exit \$?\"; '{lepp}' certify '$f' mesh-\$e --min-angle 20 --exempt-small-input-angles; echo \"exit \$?\"; done"
done < <(find "$root/corpus" \( -name '*.poly' -o -name '*.node' \) -not -path '*/regressions/fuzz*' | sort)

# The audit on its built-in sources, lepp's engines and a program (the test mesher, if built).
cache_off=(--no-cache -j 2 --root "$root")  # one corpus for both builds: its paths are in the reports
run audit-fast {lepp} audit --engine fast --sources gen,paper,corpus --cases 60 --compare reference "${cache_off[@]}" --junit junit.xml --json-file report.json --out findings
run audit-reference-midpoint {lepp} audit --engine reference --method midpoint --theta 20 --sources paper,corpus --cases 40 --compare fast "${cache_off[@]}" --json --out findings
run audit-cgal {lepp} audit --engine cgal --sources paper,gen --cases 20 --compare none "${cache_off[@]}" --out findings
run audit-usage {lepp} audit --engine nonsense
mesher=${LEPP_TEST_MESHER:-}
if [[ -n $mesher && -x $mesher ]]; then
  run audit-mesher-bug {lepp} audit --cmd "$mesher {in} {out} {theta} {method} --bug area-centroid" --sources paper,gen --cases 30 --compare none "${cache_off[@]}" --shrink-seconds 20 --json-file report.json --out findings
fi
run theorems {lepp} theorems --only Theorem2.TerminalTrianglesLargestAngleAtMost120 Lemma4.BisectionImprovesTBLeavesObtuseTA Proposition6.MidpointNearestVertexInDelaunayMesh

if diff -r -q "$work/old" "$work/new" > "$work/differences.txt"; then
  echo "compare_outputs: $n cases, identical (timings, commit and work paths masked)"
  exit 0
fi
echo "compare_outputs: $(wc -l < "$work/differences.txt") of the files differ in $n cases:" >&2
head -40 "$work/differences.txt" >&2
exit 1
