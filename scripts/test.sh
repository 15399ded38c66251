#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The test job: install, build, run every test (ctest), then each extra check in
# scripts/ci.d/ (sanitizer build, the example outside project, ...), in name order.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)"
for extra in scripts/ci.d/*.sh; do
  [ -e "$extra" ] || continue
  echo "== $extra"
  bash "$extra"
done
