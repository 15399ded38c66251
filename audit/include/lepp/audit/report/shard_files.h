// SPDX-License-Identifier: GPL-3.0-or-later
// `lepp audit merge`: the shards' JSON reports read from their files and merged (report/shard.h).
#pragma once
#include <string>
#include <vector>

#include "lepp/audit/audit.h"

namespace lepp::audit {

// The whole audit's report from the shard reports in `paths` (merge_shards: the
// findings copied to `out_dir`, the ones not found named in `warnings`).
// `json_out`: the file the merged JSON report will be written to ("" or "-": none),
// refused when it is one of the shards. Throws UsageError for that, for a file that
// cannot be read or is not JSON, for a report lacking a field or with a wrong one,
// and for whatever merge_shards refuses.
AuditReport merge_shard_files(const std::vector<std::string>& paths, const std::string& out_dir,
                              const std::string& json_out, std::vector<std::string>& warnings);

}  // namespace lepp::audit
