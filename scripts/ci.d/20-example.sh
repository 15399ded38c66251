#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# lepp as a package: install build/ into a temporary prefix, then configure,
# build and run examples/outside_project and examples/audit_engine against it (find_package(lepp)).
# LEPP_BUILD_DIR overrides the build directory (default build/, made by scripts/build.sh).
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${LEPP_BUILD_DIR:-build}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
cmake -S examples/outside_project -B "$work/example" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$work/prefix"
cmake --build "$work/example"
RC_PARAMS="${RC_PARAMS:-seed=20261122 max_success=100}" "$work/example/cdt_property"
# examples/audit_engine: a C++ engine audited in process with lepp::audit.
cmake -S examples/audit_engine -B "$work/audit" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$work/prefix"
cmake --build "$work/audit"
"$work/audit/audit_my_engine"
