// SPDX-License-Identifier: GPL-3.0-or-later
// Shewchuk's Triangle, the triangle-wasm build run under node by
// tools/triangle/triangle.js: the command line, and one run of it.
// Used by `lepp paper` and by `lepp audit --engine triangle`.
#pragma once
#include <cstdint>
#include <string>

namespace lepp::others {

// root: the source tree (holds tools/triangle/). True when node and the
// installed triangle-wasm package are there (scripts/install-deps.sh runs `npm ci`).
bool triangle_available(const std::string& root);

// `node ROOT/tools/triangle/triangle.js POLY -pqTHETA[S BUDGET] PREFIX`, shell-quoted.
// budget > 0 adds Triangle's own Steiner budget (-S), so a run above its range ends.
std::string triangle_command(const std::string& root, const std::string& poly, double theta, std::int64_t budget,
                             const std::string& prefix);

struct TriangleRun {
  int status = -1;              // triangle.js's exit status: 0 ok, 1 Triangle failed, 2 bad input, 77 not installed
  std::int64_t points_added = -1;  // from its "points added N" line
  std::string output;           // stdout and stderr
  double seconds = 0;
};

// Runs it to the end (no timeout: use -S), writes PREFIX.node/.ele/.poly.
TriangleRun run_triangle(const std::string& root, const std::string& poly, double theta, std::int64_t budget,
                         const std::string& prefix);

}  // namespace lepp::others
