# shellcheck shell=bash
# SPDX-License-Identifier: GPL-3.0-or-later
# CI's fuzz rows, sourced by scripts/ci.d/35-fuzz-bands.sh and by the benches that
# measure them (bench/fuzz_throughput.sh, bench/fuzz_campaign_rates.sh): one list, so
# that the three run the same targets in the same bands with the same environment.

# NAME TARGET RUNS [VAR=VALUE ...]: the bands where the paper claims termination
# (centroid 10 to 30 degrees, midpoint 10 to 22), the precision families in the mix.
# shellcheck disable=SC2034  # read by the scripts that source this file
fuzz_ci_rows=(
  "parse fuzz_parse 20000"
  "cdt fuzz_cdt 2000"
  "refine-centroid fuzz_refine 500 LEPP_FUZZ_METHOD=centroid LEPP_FUZZ_THETA=10:30"
  "refine-midpoint fuzz_refine 500 LEPP_FUZZ_METHOD=midpoint LEPP_FUZZ_THETA=10:22"
  "refine-precision fuzz_refine 300 LEPP_FUZZ_METHOD=centroid LEPP_FUZZ_THETA=10:30 LEPP_FUZZ_PRECISION=1"
  "differential fuzz_differential 1000"
  "engine-lepp fuzz_engine 200 LEPP_FUZZ_METHOD=centroid LEPP_FUZZ_THETA=20:30"
  "audit fuzz_audit 5000"
)

# One row's environment, into the array row_env: the known findings kept in WORK/known,
# the row's variables, and for fuzz_engine `lepp refine` on its traces (WORK/engine its
# scratch). usage: fuzz_row_env WORK TARGET LEPP [VAR=VALUE ...]
fuzz_row_env() {
  local work=$1 target=$2 lepp=$3
  shift 3
  row_env=(LEPP_FUZZ_KNOWN_DIR="$work/known" "$@")
  if [[ $target == fuzz_engine ]]; then
    row_env+=("LEPP_ENGINE_CMD=$lepp refine {in} -o {out} --min-angle {theta} --method {method} --trace -q"
              LEPP_ENGINE_TIMEOUT=60 LEPP_ENGINE_WORK="$work/engine")
  fi
}
