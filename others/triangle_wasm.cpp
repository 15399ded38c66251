// SPDX-License-Identifier: GPL-3.0-or-later
#include "triangle_wasm.h"

#include "shell_command.h"

#include <chrono>
#include <cstdio>

#include <fmt/format.h>

namespace lepp::others {
bool triangle_available(const std::string& root) {
  std::string out;
  return run_shell("node --version >/dev/null 2>&1 && test -f " +
                   shell_quote(root + "/tools/triangle/node_modules/triangle-wasm/package.json"),
               out) == 0;
}

std::string triangle_command(const std::string& root, const std::string& poly, double theta, std::int64_t budget,
                             const std::string& prefix) {
  std::string switches = fmt::format("-pq{}", theta);
  if (budget > 0) switches += fmt::format("S{}", budget);
  return fmt::format("node {} {} {} {}", shell_quote(root + "/tools/triangle/triangle.js"), shell_quote(poly), switches, shell_quote(prefix));
}

TriangleRun run_triangle(const std::string& root, const std::string& poly, double theta, std::int64_t budget,
                         const std::string& prefix) {
  TriangleRun r;
  auto t0 = std::chrono::steady_clock::now();
  r.status = run_shell(triangle_command(root, poly, theta, budget, prefix) + " 2>&1", r.output);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  long long added = -1;
  if (r.status == 0 && std::sscanf(r.output.c_str(), "points added %lld", &added) == 1) r.points_added = added;
  return r;
}

}  // namespace lepp::others
