// SPDX-License-Identifier: GPL-3.0-or-later
// One audit over many machines (docs/AUDIT.md, "Over many machines"): `lepp
// audit --shard K/N` runs the K-th of N disjoint slices of the audit's cases (a
// case is one input at one theta, with its --repeat runs: they are compared
// with each other, so they stay together), and `lepp audit merge` combines the
// shards' JSON reports into the report the whole audit gives.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lepp/audit/audit.h"

namespace lepp::audit {

struct ShardSpec {
  std::size_t index = 1, count = 1;  // K and N of "K/N", 1 <= K <= N
};

// "K/N" with 1 <= K <= N; throws UsageError naming what is wrong.
ShardSpec parse_shard(const std::string& text);

// Whether case `case_index` of the whole audit (0-based, in the audit's case
// order) belongs to shard K of N: dealt in turn (case i to shard i mod N + 1),
// so the shards' sizes differ by at most one.
bool in_shard(std::size_t case_index, std::size_t shard_index, std::size_t shard_count);

// What the shards of one audit must share, as JSON: the program, method,
// angles, seed, the inputs (their number and a hash of their contents), the
// limits and checks that decide verdicts, the comparisons, N and the number of
// cases. merge_shards refuses shards whose configs differ.
nlohmann::json shard_config(const AuditOptions& options, const std::vector<AuditInput>& inputs, std::size_t total_cases);

// A shard report's ShardData as JSON (json_report's "shard"; merge_shards reads it).
nlohmann::json shard_to_json(const AuditReport& shard_report);

struct MergeInput {
  nlohmann::json report;  // a shard's `--json` report
  std::string path;       // the file it was read from: its findings are looked for beside it
};

// The whole audit's report from the reports of all its shards: counts summed,
// firsts and lists in the whole audit's case order, the saved findings the
// whole audit would have saved (the same per-row limit, one per input, the same
// numbering), each copied from its shard's directory to `out_dir`/ROW-N with
// its paths rewritten. Timings are summed. A shard's finding directory is
// looked for beside its JSON file (in the directory named like its --out), then
// where the shard wrote it; one not found is named in `warnings`. Throws
// UsageError for reports that are not shards, shards of different configs or
// counts, and missing or duplicate shards.
AuditReport merge_shards(const std::vector<MergeInput>& shards, const std::string& out_dir, std::vector<std::string>& warnings);

}  // namespace lepp::audit
