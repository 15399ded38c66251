#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The main job: install, build, then reproduce the paper's empirical study with
# `lepp paper`: the four paper problems refined by Lepp-centroid, Lepp-midpoint,
# CGAL's mesher and Triangle at 10 to 36 degrees and above. Prints the table of
# Steiner points and smallest angles, writes docs/PAPER.md and docs/paper/.
# Pass --quick for a smaller run (budget 5000, no readings), other options go to `lepp paper`.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
./build/cli/lepp paper --out docs --work out/paper "$@"
