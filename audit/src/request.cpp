// SPDX-License-Identifier: GPL-3.0-or-later
// `lepp audit`'s options turned into AuditOptions, the engines apart; bad usage refused.
#include "lepp/audit/request.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "lepp/audit/inputs/points_cache.h"
#include "lepp/audit/report/shard.h"

namespace lepp::audit {

std::vector<std::string> comma_list(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  std::string p;
  while (std::getline(in, p, ','))
    if (!p.empty()) parts.push_back(p);
  return parts;
}

void apply_request(const AuditRequest& a, AuditOptions& o) {
  o.thetas = a.thetas;
  o.cases = a.cases;
  o.inputs.seed = a.seed;
  o.inputs.dirs = a.inputs;
  o.inputs.source_root = a.root;
  const std::vector<std::string> sources = comma_list(a.sources);
  auto has = [&](const char* s) { return std::find(sources.begin(), sources.end(), s) != sources.end(); };
  for (const std::string& s : sources)
    if (s != "gen" && s != "paper" && s != "corpus") throw UsageError("--sources: unknown source " + s + " (gen, paper, corpus)");
  o.inputs.generated = has("gen");
  o.inputs.paper = has("paper");
  o.inputs.corpus = has("corpus");
  o.timeout_seconds = a.timeout;
  o.memory_mb = a.memory;
  // The replay makes exact rationals of both: a NaN or an infinity is bad usage here (in
  // the library it makes every run's conformance an internal error: the replay refuses it).
  if (!std::isfinite(a.angle_tolerance) || !std::isfinite(a.point_tolerance))
    throw UsageError("--angle-tolerance and --point-tolerance must be finite numbers");
  o.checks.angle_tolerance_deg = a.angle_tolerance;
  o.checks.point_tolerance_ulps = a.point_tolerance;
  // A finding's reproduce.sh repeats the readings declared, so it judges the same way.
  o.checks.area_centroid = a.centroid == "area";
  if (o.checks.area_centroid) o.reproduce_prefix += " --centroid area";
  o.checks.arithmetic_double = a.arithmetic == "double";
  if (o.checks.arithmetic_double) o.reproduce_prefix += " --arithmetic double";
  o.checks.tie_search_states = a.tie_search_states;
  if (a.tie_search_states != kTieSearchStates) o.reproduce_prefix += " --tie-search-states " + std::to_string(a.tie_search_states);
  o.out_dir = a.out;
  o.shrink = !a.no_shrink;
  o.max_findings_per_row = a.max_findings;
  o.shrink_max_seconds = a.shrink_seconds;
  o.jobs = a.jobs;
  o.repeat = a.repeat;
  if (a.repeat < 1) throw UsageError("--repeat: at least 1");
  o.points_cache_dir = a.no_cache ? std::string() : !a.cache.empty() ? a.cache : default_points_cache_dir();
  if (!a.shard.empty()) {
    const ShardSpec spec = parse_shard(a.shard);
    o.shard_index = spec.index;
    o.shard_count = spec.count;
  }
}

}  // namespace lepp::audit
