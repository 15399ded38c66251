#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# A whole `lepp audit` of lepp's fast engine through --cmd with the default comparisons
# (lepp reference and Triangle), against the engine's own time (docs/BENCHMARKS.md,
# "A whole audit"): fresh points cache and warm, -j 1 and -j 2, CASES runs each.
# usage: bench/audit_whole.sh [LEPP] [CASES]      (default build/cli/lepp, 100)
set -euo pipefail
lepp=$(readlink -f "${1:-build/cli/lepp}")
cases=${2:-100}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmd="$lepp refine {in} -o {out} --min-angle {theta} --method {method} --trace -q"
printf '| run | -j | cache | audit s | engine s | comparisons s (runs, from cache) | audit / engine |\n|---|---:|---|---:|---:|---:|---:|\n'
for spec in "1 fresh" "1 warm" "2 fresh" "2 warm"; do
  set -- $spec
  [ "$2" = fresh ] && rm -rf "$work/cache-$1"
  "$lepp" audit --cmd "$cmd" --cases "$cases" -j "$1" --cache "$work/cache-$1" --out "$work/out" --json > "$work/r.json"
  python3 -c 'import json,sys; r=json.load(open(sys.argv[1]))
print("| %d cases | %s | %s | %.2f | %.2f | %.2f (%d, %d) | %.2f |" % (r["runs"], sys.argv[2], sys.argv[3], r["seconds"],
      r["engine_seconds"], r["comparison_seconds"], r["comparison_runs"], r["comparison_cache_hits"], r["seconds"] / r["engine_seconds"]))' \
    "$work/r.json" "$1" "$2"
done
