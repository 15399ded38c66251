// SPDX-License-Identifier: GPL-3.0-or-later
// `lepp audit merge` refuses shards of audits with different settings (issue 42):
// every option of `lepp audit` that changes a verdict, a count or a saved finding,
// changed alone in the request, changes the shards' shared configuration
// (shard_config), and merge_shards then refuses the two, naming the setting and both
// values. Options that change none of these (-j, --out, the cache, the report's
// files) leave it the same, so the refusal is not of any difference at all. Kills
// audit-shard-config-no-arithmetic and its siblings (one key left out of shard_config).
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lepp/audit/report/shard.h"
#include "lepp/engines/audit_setup.h"
#include "lepp/engines/registry.h"

namespace {

using lepp::audit::AuditRequest;

AuditRequest base() {
  AuditRequest a;
  a.engine = "fast";
  a.thetas = {25};
  a.cases = 4;
  a.sources = "paper";
  a.compare = "none";
  a.no_cache = true;
  a.no_isolate = true;  // no fork server: the engines are not run here
  a.root = LEPP_SOURCE_DIR;
  a.shard = "1/2";
  return a;
}

nlohmann::json config_of(const AuditRequest& a) {
  const lepp::engines::AuditSetup setup = lepp::engines::audit_setup(a);
  std::vector<std::string> skipped;
  const auto inputs = lepp::audit::collect_inputs(setup.options.inputs, skipped);
  return lepp::audit::shard_config(setup.options, inputs, 4);
}

nlohmann::json shard_report(std::size_t index, const nlohmann::json& config) {
  return {{"lepp_version", "test"}, {"shard", {{"index", index}, {"count", 2}, {"config", config}}}};
}

struct Setting {
  std::string what;  // the option as a user writes it
  std::string key;   // the configuration's field the merge names
  std::function<void(AuditRequest&)> change;
};

std::vector<Setting> verdict_settings() {
  std::vector<Setting> s = {
      {"--arithmetic double", "arithmetic", [](AuditRequest& a) { a.arithmetic = "double"; }},
      {"--centroid area", "centroid", [](AuditRequest& a) { a.centroid = "area"; }},
      {"--angle-tolerance 0", "angle_tolerance", [](AuditRequest& a) { a.angle_tolerance = 0; }},
      {"--point-tolerance 16", "point_tolerance", [](AuditRequest& a) { a.point_tolerance = 16; }},
      {"--method midpoint", "method", [](AuditRequest& a) { a.method = "midpoint"; }},
      {"--engine reference", "engine", [](AuditRequest& a) { a.engine = "reference"; }},
      {"--cmd", "engine", [](AuditRequest& a) { a.engine.clear(), a.cmd = "/bin/true {in} {out}"; }},
      {"--theta 30", "thetas", [](AuditRequest& a) { a.thetas = {30}; }},
      {"--seed 2", "seed", [](AuditRequest& a) { a.seed = 2; }},
      {"--cases 6", "cases", [](AuditRequest& a) { a.cases = 6; }},
      {"--sources paper,corpus", "inputs", [](AuditRequest& a) { a.sources = "paper,corpus"; }},
      {"--inputs A.poly", "inputs", [](AuditRequest& a) { a.inputs = {std::string(LEPP_SOURCE_DIR) + "/corpus/paper/A.poly"}; }},
      {"--timeout 20", "timeout", [](AuditRequest& a) { a.timeout = 20; }},
      {"--memory 512", "memory_mb", [](AuditRequest& a) { a.memory = 512; }},
      {"--repeat 2", "repeat", [](AuditRequest& a) { a.repeat = 2; }},
      {"--no-shrink", "shrink", [](AuditRequest& a) { a.no_shrink = true; }},
      {"--max-findings 5", "max_findings", [](AuditRequest& a) { a.max_findings = 5; }},
      {"--shrink-seconds 30", "shrink_max_seconds", [](AuditRequest& a) { a.shrink_seconds = 30; }},
      {"--compare reference", "compare", [](AuditRequest& a) { a.compare = "reference"; }},
      {"--tie-search-states 64", "tie_search_states", [](AuditRequest& a) { a.tie_search_states = 64; }},
  };
  // Every processing order of the built-in engines other than the default.
  for (lepp::QueueOrder order : lepp::engines::audit_orders())
    if (order != lepp::QueueOrder::Fifo)
      s.push_back({std::string("--order ") + lepp::to_string(order), "engine",
                   [order](AuditRequest& a) { a.order = lepp::to_string(order); }});
  return s;
}

TEST(ShardSettings, MergeRefusesShardsOfDifferentSettingsNamingBothValues) {
  const nlohmann::json one = config_of(base());
  for (const Setting& s : verdict_settings()) {
    SCOPED_TRACE(s.what);
    AuditRequest changed = base();
    s.change(changed);
    const nlohmann::json other = config_of(changed);
    ASSERT_NE(one.value(s.key, nlohmann::json()), other.value(s.key, nlohmann::json())) << "the configuration misses it";
    std::vector<lepp::audit::MergeInput> shards = {{shard_report(1, one), "a.json"}, {shard_report(2, other), "b.json"}};
    std::vector<std::string> warnings;
    try {
      lepp::audit::merge_shards(shards, testing::TempDir() + "lepp-shard-settings", warnings);
      ADD_FAILURE() << "merged";
    } catch (const lepp::audit::UsageError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("a.json and b.json are shards of different audits"), std::string::npos) << m;
      // The first field that differs is named with both values (--sources changes the
      // inputs' count and hash, --cmd the engine: one field named, whichever comes first).
      if (m.find(" " + s.key + " is ") != std::string::npos) {
        EXPECT_NE(m.find(one.value(s.key, nlohmann::json()).dump()), std::string::npos) << m;
        EXPECT_NE(m.find(other.value(s.key, nlohmann::json()).dump()), std::string::npos) << m;
      } else {
        ADD_FAILURE() << "the message does not name " << s.key << ": " << m;
      }
    }
  }
}

// The arithmetic case as a user meets it, the message whole.
TEST(ShardSettings, ExactAgainstDoubleArithmeticIsNamed) {
  AuditRequest d = base();
  d.arithmetic = "double";
  std::vector<lepp::audit::MergeInput> shards = {{shard_report(1, config_of(base())), "exact.json"},
                                                 {shard_report(2, config_of(d)), "double.json"}};
  std::vector<std::string> warnings;
  try {
    lepp::audit::merge_shards(shards, testing::TempDir() + "lepp-shard-settings", warnings);
    ADD_FAILURE() << "merged";
  } catch (const lepp::audit::UsageError& e) {
    EXPECT_STREQ(e.what(),
                 "exact.json and double.json are shards of different audits: arithmetic is \"exact\" in one, \"double\" in the other");
  }
}

// What does not change a verdict may differ between the machines of one audit.
TEST(ShardSettings, JobsOutputAndCacheMayDiffer) {
  const nlohmann::json one = config_of(base());
  const std::vector<std::function<void(AuditRequest&)>> free = {
      [](AuditRequest& a) { a.jobs = 7; },
      [](AuditRequest& a) { a.out = "elsewhere"; },
      [](AuditRequest& a) { a.no_cache = false, a.cache = "/tmp/lepp-cache-elsewhere"; },
      [](AuditRequest& a) { a.json = true, a.json_file = "x.json", a.junit = "x.xml"; },
      [](AuditRequest& a) { a.shard = "2/2"; },
  };
  for (std::size_t i = 0; i < free.size(); ++i) {
    AuditRequest a = base();
    free[i](a);
    EXPECT_EQ(config_of(a), one) << "change " << i;
  }
}

}  // namespace
