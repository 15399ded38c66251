#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs a fuzz campaign from a plan, one lane after the other, and prints the
# rows of docs/FUZZING.md's findings table (fuzz/summarize_logs.py).
#   fuzz/campaign.sh PLAN [LANE]
# A plan has one segment per line: NAME SECONDS TARGET [VAR=VALUE ...]
# (blank lines and # comments are skipped). LANE (default: every line) runs
# only the segments whose NAME starts with it, so two lanes can share a plan on
# two cores (build first, then run the lanes as built):
#   fuzz/campaign.sh --build PLAN
#   LEPP_FUZZ_NO_BUILD=1 fuzz/campaign.sh PLAN A & LEPP_FUZZ_NO_BUILD=1 fuzz/campaign.sh PLAN B
# Each segment is fuzz/run.sh TARGET SECONDS with its variables (quoted as in
# a shell: LEPP_ENGINE_CMD='lepp refine {in} ...'; $root is the source tree); the log is
# $LEPP_FUZZ_WORK/campaign/NAME.log (default out/fuzz). LEPP_FUZZ_NICE (default
# 5) is the niceness of the fuzzers.
set -euo pipefail
build_only=0
[[ ${1:-} == --build ]] && build_only=1 && shift
if [[ $# -lt 1 ]]; then
  echo "usage: fuzz/campaign.sh [--build] PLAN [LANE]" >&2
  exit 2
fi
plan=$1 lane=${2:-}
root=$(cd "$(dirname "$0")/.." && pwd)
logs=${LEPP_FUZZ_WORK:-$root/out/fuzz}/campaign
mkdir -p "$logs"
[[ -f $plan ]] || { echo "fuzz/campaign.sh: $plan: no such plan" >&2; exit 2; }
line_no=0
names=()
while read -r name seconds target rest; do
  line_no=$((line_no + 1))
  [[ -z ${name:-} || $name == \#* ]] && continue
  if [[ -z ${target:-} || ! $seconds =~ ^[0-9]+$ ]]; then
    echo "fuzz/campaign.sh: $plan:$line_no: expected NAME SECONDS TARGET [VAR=VALUE ...]" >&2
    exit 2
  fi
  [[ -n $lane && $name != "$lane"* ]] && continue
  eval "vars=(${rest:-})"  # the plan's own quoting
  if [[ $build_only == 1 ]]; then
    LEPP_FUZZ_NO_BUILD=0 bash "$root/fuzz/run.sh" "$target" build ||
      { echo "fuzz/campaign.sh: building $target failed (fuzz/run.sh $target build)" >&2; exit 1; }
    continue
  fi
  echo "campaign: $name: $target for $seconds s ${vars[*]}" >&2
  status=0
  env "${vars[@]}" LEPP_FUZZ_NO_BUILD=${LEPP_FUZZ_NO_BUILD:-0} nice -n "${LEPP_FUZZ_NICE:-5}" \
    bash "$root/fuzz/run.sh" "$target" "$seconds" >"$logs/$name.log" 2>&1 </dev/null || status=$?
  echo "campaign: $name: exit $status, log $logs/$name.log" >&2
  names+=("$logs/$name.log")
done < <(sed 's/[[:space:]]*$//' "$plan")
if [[ ${#names[@]} -gt 0 ]]; then python3 "$root/fuzz/summarize_logs.py" "${names[@]}"; fi
