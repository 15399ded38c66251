// SPDX-License-Identifier: GPL-3.0-or-later
// The reference engine's memo of longest edges (src/longest_edge_memo.h), an
// open-addressing table, against std::map: every face's ids find the answer kept for
// them and no other, across the table's growth, ids near the int range's ends included.
#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <map>
#include <random>

#include "../src/longest_edge_memo.h"

namespace lepp::reference::detail {
namespace {

TEST(LongestEdgeMemo, EachFaceFindsItsOwnAnswer) {
  LongestEdgeMemo memo;
  std::map<LongestEdgeMemo::Ids, int> oracle;
  std::mt19937 rng(7);
  // Few distinct ids (faces share them, as a mesh's do) and a few at the range's ends.
  std::uniform_int_distribution<int> id(0, 60), pick(0, 9);
  auto ids = [&]() {
    LongestEdgeMemo::Ids t{id(rng), id(rng), id(rng)};
    if (pick(rng) == 0) t[2] = INT_MAX - id(rng);
    std::sort(t.begin(), t.end());
    return t;
  };
  for (int step = 0; step < 40000; ++step) {
    const LongestEdgeMemo::Ids t = ids();
    int& answer = memo.at(t);
    const auto known = oracle.find(t);
    if (known == oracle.end()) {
      ASSERT_EQ(answer, -1) << "step " << step << ": a new face's slot is not empty";
      answer = t[static_cast<std::size_t>(step % 3)];
      oracle.emplace(t, answer);
    } else {
      ASSERT_EQ(answer, known->second) << "step " << step << ": " << t[0] << " " << t[1] << " " << t[2];
    }
    ASSERT_EQ(memo.size(), oracle.size());
  }
  EXPECT_GT(oracle.size(), 10000u);  // grown many times over
  EXPECT_LT(oracle.size(), 40000u);  // and asked again for faces it kept
}

}  // namespace
}  // namespace lepp::reference::detail
