// SPDX-License-Identifier: GPL-3.0-or-later
// --shard K/N: the values accepted and refused, and the slices a partition of
// the cases (every case in exactly one shard, the sizes within one).
#include <gtest/gtest.h>

#include <vector>

#include "lepp/audit/report/shard.h"

namespace lepp::audit {
namespace {

TEST(Shard, ParsesKOfN) {
  EXPECT_EQ(parse_shard("1/1").index, 1u);
  const ShardSpec s = parse_shard("3/8");
  EXPECT_EQ(s.index, 3u);
  EXPECT_EQ(s.count, 8u);
  for (const char* bad : {"", "0/3", "4/3", "3/0", "3", "/3", "1/", "a/b", "1/3/4", "-1/3", "1.5/3", " 1/3", "1/3 "})
    EXPECT_THROW(parse_shard(bad), UsageError) << bad;
}

TEST(Shard, EveryCaseInExactlyOneShard) {
  for (std::size_t n = 1; n <= 9; ++n)
    for (std::size_t cases : {0u, 1u, 2u, 7u, 100u, 301u}) {
      std::vector<std::size_t> sizes(n, 0);
      for (std::size_t c = 0; c < cases; ++c) {
        std::size_t owners = 0;
        for (std::size_t k = 1; k <= n; ++k)
          if (in_shard(c, k, n)) ++owners, ++sizes[k - 1];
        ASSERT_EQ(owners, 1u) << "case " << c << " of " << cases << ", N " << n;
      }
      for (std::size_t k = 0; k < n; ++k) EXPECT_LE(sizes[k] - sizes[n - 1], 1u) << "N " << n;
    }
}

}  // namespace
}  // namespace lepp::audit
