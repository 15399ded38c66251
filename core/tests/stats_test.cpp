// SPDX-License-Identifier: GPL-3.0-or-later
// The statistics the CLI, Python and the paper runner print (lepp/stats.h).
#include <gtest/gtest.h>

#include "lepp/refine.h"
#include "lepp/stats.h"

namespace lepp {
namespace {

TEST(RefineStatistics, AverageLeppSizeIsTrianglesPerSearch) {
  RefineResult r;
  r.lepp_searches = 4;
  r.lepp_triangles = 10;
  EXPECT_DOUBLE_EQ(average_lepp_size(r), 2.5);
  r.lepp_searches = 0;  // nothing refined: 0, not a division by zero
  r.lepp_triangles = 0;
  EXPECT_EQ(average_lepp_size(r), 0.0);
}

}  // namespace
}  // namespace lepp
