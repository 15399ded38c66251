// SPDX-License-Identifier: GPL-3.0-or-later
// The chain's summary as a decision table (issue 42; judge/chain_summary.h): a
// conformance failure is "one consistent variant" only when the replay reached the
// trace's end with that one name allowed and the name is a rule set. A chain that
// stopped before the trace's end (a later step the replay could not follow) must
// not be called one consistent variant. Kills audit-chain-stopped-called-consistent,
// audit-chain-of-two-called-consistent and audit-chain-any-name-called-consistent.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "judge/chain_summary.h"

namespace {

using lepp::audit::ConformanceFailure;
using lepp::audit::DeviationLink;

ConformanceFailure failure(const std::vector<std::string>& chain, bool complete) {
  ConformanceFailure f;
  f.deviation = chain.front();
  for (std::size_t i = 0; i < chain.size(); ++i) f.chain.push_back({chain[i], 3 + 10 * i, 5});
  f.chain_complete = complete;
  if (!complete) f.chain_end = "step 40 is area-centroid's point at a configuration the replay cannot reach with it";
  return f;
}

struct Row {
  std::vector<std::string> chain;
  bool complete;
  bool consistent;
};

TEST(ChainSummary, OneConsistentVariantOnlyForAWholeTraceOfOneRuleSet) {
  const std::vector<Row> table = {
      {{"area-centroid"}, true, true},
      {{"area-centroid"}, false, false},  // stopped before the trace's end
      {{"remark10-reversed"}, true, true},
      {{"remark10-reversed"}, false, false},
      {{"inexact-length"}, true, true},
      {{"area-centroid", "other-second-longest"}, true, false},  // two names
      {{"area-centroid", "unknown"}, false, false},
      {{"circumcenter"}, true, false},  // a single point rule, no rule set to follow
      {{"unknown"}, true, false},
      {{"missing-flips"}, true, false},  // not a catalogue name
  };
  for (const Row& r : table) {
    std::string name;
    for (const std::string& n : r.chain) name += n + " ";
    EXPECT_EQ(lepp::audit::fits_one_variant(failure(r.chain, r.complete)), r.consistent)
        << name << (r.complete ? "to the trace's end" : "stopped");
  }
}

TEST(ChainSummary, DeviationNamedReadsEveryCatalogueName) {
  for (int k = 0; k < lepp::audit::kDeviations; ++k) {
    const auto d = static_cast<lepp::audit::Deviation>(k);
    EXPECT_EQ(lepp::audit::deviation_named(lepp::audit::to_string(d)), d) << lepp::audit::to_string(d);
  }
  EXPECT_EQ(lepp::audit::deviation_named("missing-flips"), lepp::audit::Deviation::Unknown);
}

}  // namespace
