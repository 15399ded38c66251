#!/usr/bin/env bash
# The main job: install, build, refine the paper's four problems with both
# methods at 20 to 34 degrees and print a table of Steiner points and smallest angles.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
mkdir -p out/main
printf '%-12s %-9s %5s %8s %10s %s\n' problem method theta steiner min_angle outcome
for problem in square400 circles240 rect162 A; do
  for method in centroid midpoint; do
    for theta in 20 25 28 30 32 34; do
      json=$(./build/cli/lepp refine "corpus/paper/$problem.poly" -o "out/main/$problem-$method-$theta" \
               --min-angle "$theta" --method "$method" --json || true)
      printf '%-12s %-9s %5s %8s %10.3f %s\n' "$problem" "$method" "$theta" \
        "$(echo "$json" | sed -n 's/.*"steiner_points": \([0-9]*\).*/\1/p')" \
        "$(echo "$json" | sed -n 's/.*"min_angle": \([0-9.e+-]*\).*/\1/p')" \
        "$(echo "$json" | sed -n 's/.*"outcome": "\([a-z-]*\)".*/\1/p')"
    done
  done
done
