// SPDX-License-Identifier: GPL-3.0-or-later
// `lepp audit`'s options as typed (AuditRequest), and what the audit makes of them
// without knowing any engine: the inputs, limits, checks, shrinking, jobs, cache and
// shard. The engine under audit and the comparisons are named by the engines' registry
// (lepp/engines/audit_setup.h turns a whole request into the engine and AuditOptions).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "lepp/audit/audit.h"

namespace lepp::audit {

// Every option of `lepp audit`, with its defaults (docs/AUDIT.md).
struct AuditRequest {
  std::string cmd, engine;  // exactly one: a command template, or a built-in engine's name
  std::string method = lepp::to_string(Method::Centroid);
  std::string order = lepp::to_string(QueueOrder::Fifo);  // of lepp's built-in engines
  std::vector<double> thetas = {20, 25, 30};
  std::size_t cases = 300;
  std::uint64_t seed = 1;
  std::vector<std::string> inputs;
  std::string sources = "gen,paper,corpus";
  std::string compare = "auto";  // comma-separated engine names, "none", or "auto"
  std::string root;  // empty: share/lepp beside the executable, else the source tree (inputs/data_root.h)
  double timeout = 10;
  std::size_t memory = 0;
  double angle_tolerance = 1e-3, point_tolerance = 8;
  std::size_t tie_search_states = kTieSearchStates;  // of the certificate and lepp's built-in engines
  std::string centroid = "vertex";   // or "area"
  std::string arithmetic = "exact";  // or "double"
  std::string out = "audit-out";
  std::string junit, json_file;
  bool json = false, no_shrink = false, no_isolate = false;
  std::size_t max_findings = 3;
  double shrink_seconds = 60;
  std::size_t jobs = 0;  // 0: the machine's cores
  std::size_t repeat = 1;
  std::string cache;     // empty: the default cache directory
  bool no_cache = false;
  std::string shard;     // K/N; empty: the whole audit
};

// The non-empty items of a comma-separated list ("gen,,paper": gen, paper).
std::vector<std::string> comma_list(const std::string& text);

// Sets every field of `options` the request decides apart from the engines (inputs
// from request.root as given: resolve it first), and appends the readings declared
// (--centroid area, --arithmetic double) to options.reproduce_prefix. Throws
// UsageError, in this order: an unknown --sources name, a tolerance that is not
// finite, --repeat 0, a malformed --shard.
void apply_request(const AuditRequest& request, AuditOptions& options);

}  // namespace lepp::audit
