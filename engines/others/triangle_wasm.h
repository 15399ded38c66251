// SPDX-License-Identifier: GPL-3.0-or-later
// Shewchuk's Triangle, the triangle-wasm build run under node by
// tools/triangle/triangle.js: the command line, and one run of it.
// Used by `lepp paper` and by `lepp audit --engine triangle`.
#pragma once
#include <sys/types.h>

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

// One long-lived `node triangle.js --serve` fed many cases over a pipe, so a
// case costs Triangle's time, not node's start and the wasm's load (issue 19:
// one node process per case was most of an audit's time). Started on the first
// case; a case past its timeout kills it (the next case starts another). Not
// thread-safe: one per thread.
class TriangleServer {
 public:
  explicit TriangleServer(std::string root);
  ~TriangleServer();
  TriangleServer(const TriangleServer&) = delete;
  TriangleServer& operator=(const TriangleServer&) = delete;

  // As run_triangle, within timeout_seconds (<= 0: none): status -1 and `output`
  // saying why when the server could not start, died or was killed at the timeout.
  TriangleRun run(const std::string& poly, double theta, std::int64_t budget, const std::string& prefix,
                  double timeout_seconds);
  std::size_t starts() const { return starts_; }  // node processes started so far

 private:
  bool start(std::string& why);
  void stop();

  std::string root_;
  pid_t pid_ = -1;
  int to_node_ = -1, from_node_ = -1;
  std::string pending_;  // read past the last answer
  std::size_t starts_ = 0;
};

}  // namespace lepp::others
