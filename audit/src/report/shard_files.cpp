// SPDX-License-Identifier: GPL-3.0-or-later
// `lepp audit merge`: the shards' JSON reports read from their files and merged (report/shard.h).
#include "lepp/audit/report/shard_files.h"

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "lepp/audit/engine.h"
#include "lepp/audit/report/shard.h"

namespace lepp::audit {

AuditReport merge_shard_files(const std::vector<std::string>& paths, const std::string& out_dir,
                              const std::string& json_out, std::vector<std::string>& warnings) {
  std::vector<MergeInput> shards;
  for (const std::string& path : paths) {
    // Writing the merged report over a shard's would lose that shard before it is read again.
    if (!json_out.empty() && json_out != "-" && std::filesystem::exists(json_out) && std::filesystem::exists(path) &&
        std::filesystem::equivalent(json_out, path))
      throw UsageError("--json " + json_out + " is one of the shard reports: give another file");
    std::ifstream in(path);
    if (!in) throw UsageError("cannot read " + path);
    nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    if (j.is_discarded()) throw UsageError(path + " is not JSON (a shard's report is lepp audit --shard K/N --json)");
    shards.push_back({std::move(j), path});
  }
  try {
    return merge_shards(shards, out_dir, warnings);
  } catch (const nlohmann::json::exception& e) {
    // A hand-edited or truncated report: bad usage, not an internal error.
    throw UsageError(std::string("a shard report lacks a field or has a wrong one: ") + e.what());
  }
}

}  // namespace lepp::audit
