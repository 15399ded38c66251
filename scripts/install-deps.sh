#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs everything lepp needs on Debian 12 (run as root). Debian packages only,
# plus Node.js's npm from Debian when the machine has no npm yet. dpkg-dev and file:
# cpack -G DEB reads the command's shared-library dependencies with them. pybind11-dev,
# python3-dev, python3-numpy: the Python package (python/); pytest, Hypothesis: its tests.
# meshio and Gmsh (its program and Python API) read back the .vtu and .msh files in tests/formats.
# chromium and python3-pil: the HTML reports opened, screenshotted and checked in a real browser (scripts/ci.d/50-html-browser.sh).
# libz3-dev: `lepp theorems --prove` (properties/prove); z3 and qepcad: the obligation files'
# re-check in CI (scripts/ci.d/50-proofs.sh), qepcad also the prover's second procedure.
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
apt-get update
apt-get install -y --no-install-recommends \
  build-essential cmake ninja-build ccache pkg-config git \
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev \
  librapidcheck-dev libgtest-dev libgmock-dev libbenchmark-dev \
  clang-14 libclang-rt-14-dev libfuzzer-14-dev \
  libcli11-dev nlohmann-json3-dev libfmt-dev \
  python3-matplotlib zip \
  pybind11-dev python3-dev python3-numpy python3-pytest python3-hypothesis \
  python3-meshio gmsh python3-gmsh \
  dpkg-dev file gcovr llvm-14 \
  chromium python3-pil \
  libz3-dev z3 qepcad libmpfi-dev
# Node.js runs Triangle (triangle-wasm) for the comparisons; some machines ship
# nodejs with npm bundled (NodeSource), where Debian's npm package conflicts.
if ! command -v node >/dev/null; then apt-get install -y --no-install-recommends nodejs; fi
if ! command -v npm >/dev/null; then apt-get install -y --no-install-recommends npm; fi
# Triangle (triangle-wasm, pinned by tools/triangle/package-lock.json) for the
# comparisons in `lepp paper`. Idempotent: skipped when already installed.
triangle_dir="$(cd "$(dirname "$0")/../tools/triangle" && pwd)"
if [ ! -f "$triangle_dir/node_modules/triangle-wasm/package.json" ]; then
  (cd "$triangle_dir" && npm ci --no-audit --no-fund)
fi
