// SPDX-License-Identifier: GPL-3.0-or-later
#include "triangle_wasm.h"

#include <sys/wait.h>

#include <chrono>
#include <cstdio>

#include <fmt/format.h>

namespace lepp::others {
namespace {

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// Runs a shell command, its stdout into `output`; returns the exit status.
int shell(const std::string& command, std::string& output) {
  output.clear();
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return -1;
  char buf[4096];
  std::size_t n;
  while ((n = fread(buf, 1, sizeof buf, pipe)) > 0) output.append(buf, n);
  int status = pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

bool triangle_available(const std::string& root) {
  std::string out;
  return shell("node --version >/dev/null 2>&1 && test -f " +
                   quote(root + "/tools/triangle/node_modules/triangle-wasm/package.json"),
               out) == 0;
}

std::string triangle_command(const std::string& root, const std::string& poly, double theta, std::int64_t budget,
                             const std::string& prefix) {
  std::string switches = fmt::format("-pq{}", theta);
  if (budget > 0) switches += fmt::format("S{}", budget);
  return fmt::format("node {} {} {} {}", quote(root + "/tools/triangle/triangle.js"), quote(poly), switches, quote(prefix));
}

TriangleRun run_triangle(const std::string& root, const std::string& poly, double theta, std::int64_t budget,
                         const std::string& prefix) {
  TriangleRun r;
  auto t0 = std::chrono::steady_clock::now();
  r.status = shell(triangle_command(root, poly, theta, budget, prefix) + " 2>&1", r.output);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  long long added = -1;
  if (r.status == 0 && std::sscanf(r.output.c_str(), "points added %lld", &added) == 1) r.points_added = added;
  return r;
}

}  // namespace lepp::others
