#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The test job: install, build, run every test (ctest), then each extra check in
# scripts/ci.d/ (sanitizer build, the example outside project, ...), in name order.
set -euo pipefail
cd "$(dirname "$0")/.."
# Each part prints its seconds: CI has 90 minutes on 2 cores, and this is
# where a reader sees which part grew.
timed() {
  local start=$SECONDS
  "$@"
  echo "== $* took $(( SECONDS - start )) s"
}
timed bash scripts/install-deps.sh
timed bash scripts/build.sh
timed ctest --test-dir build --output-on-failure -j "$(nproc)"
for extra in scripts/ci.d/*.sh; do
  [ -e "$extra" ] || continue
  echo "== $extra"
  timed bash "$extra"
done
echo "== all parts: $SECONDS s"
