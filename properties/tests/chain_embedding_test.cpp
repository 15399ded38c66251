// SPDX-License-Identifier: GPL-3.0-or-later
// The check that segment chains cross nowhere (properties/certify/src/chain_embedding.h)
// at its boundaries: closed segments (an end on another edge's interior meets it), a
// shared end (meets elsewhere only along one line the same way), a vertex exactly on
// an edge against one ulp off it, and crossings a few ulps wide at 2^52.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "chain_embedding.h"

namespace lepp::certify {
namespace {

std::size_t meetings(const std::vector<Point>& pts, const std::vector<std::array<int, 2>>& edges, std::vector<char> used = {}) {
  if (used.empty()) used.assign(pts.size(), 1);
  return chain_meetings(pts, edges, used).size();
}

TEST(ChainEmbedding, CrossingEdgesMeet) {
  EXPECT_EQ(meetings({{0, 0}, {2, 2}, {0, 2}, {2, 0}}, {{0, 1}, {2, 3}}), 1u);
  EXPECT_EQ(meetings({{0, 0}, {2, 2}, {0, 3}, {3, 3}}, {{0, 1}, {2, 3}}), 0u);  // apart (boxes meet, segments do not)
}

TEST(ChainEmbedding, AnEndOnAnotherEdgeMeetsIt) {
  // (1, 0) ends the second edge and lies inside the first: a T, closed.
  const std::vector<Point> pts{{0, 0}, {2, 0}, {1, 0}, {1, 1}};
  const auto found = chain_meetings(pts, {{0, 1}, {2, 3}}, {1, 1, 1, 1});
  ASSERT_EQ(found.size(), 2u);  // the edges meet, and vertex 2 lies on edge 0
  EXPECT_EQ(meetings({{0, 0}, {2, 0}, {1, std::nextafter(0.0, 1.0)}, {1, 1}}, {{0, 1}, {2, 3}}), 0u);  // the least double above
}

TEST(ChainEmbedding, SharedEndMeetsElsewhereOnlyAlongOneLineTheSameWay) {
  EXPECT_EQ(meetings({{0, 0}, {1, 0}, {0, 1}}, {{0, 1}, {0, 2}}), 0u);             // a corner
  EXPECT_EQ(meetings({{0, 0}, {2, 0}, {1, 0}}, {{0, 1}, {0, 2}}, {1, 1, 0}), 1u);  // overlap along x (vertex 2 unused)
  EXPECT_EQ(meetings({{0, 0}, {2, 0}, {-1, 0}}, {{0, 1}, {0, 2}}), 0u);            // a straight continuation
  EXPECT_EQ(meetings({{0, 0}, {0, 2}, {0, 1}}, {{0, 1}, {2, 0}}, {1, 1, 0}), 1u);  // overlap along y, listed the other way
  EXPECT_EQ(meetings({{0, 0}, {2, 2}, {1, 1}}, {{0, 1}, {0, 2}}, {1, 1, 0}), 1u);  // along a diagonal
}

TEST(ChainEmbedding, VertexOnAnEdgeOnlyWhenInATriangle) {
  const std::vector<Point> pts{{0, 0}, {2, 0}, {1, 0}};
  EXPECT_EQ(meetings(pts, {{0, 1}}, {1, 1, 1}), 1u);
  EXPECT_EQ(meetings(pts, {{0, 1}}, {1, 1, 0}), 0u);  // in no triangle: reported by other checks, not an overlap
  EXPECT_EQ(meetings({{0, 0}, {2, 0}, {1, -std::nextafter(0.0, 1.0)}}, {{0, 1}}), 0u);
  EXPECT_EQ(meetings({{0, 0}, {2, 0}, {3, 0}}, {{0, 1}}), 0u);  // on the line, past the end
}

TEST(ChainEmbedding, NearlyParallelChainsAtTwoToThe52) {
  // Integer offsets from X = 2^52 (one ulp apart): the edge from (1, 1) to (3, 0) passes
  // above the first edge's line at x = 1 and below it at x = 3, by half an ulp each.
  const double X = std::ldexp(1.0, 52);
  auto at = [&](double x, double y) { return Point{X + x, X + y}; };
  EXPECT_EQ(meetings({at(0, 0), at(4, 2), at(1, 1), at(3, 0)}, {{0, 1}, {2, 3}}), 1u);
  EXPECT_EQ(meetings({at(0, 0), at(4, 2), at(1, 1), at(3, 2)}, {{0, 1}, {2, 3}}), 0u);  // stays above
  // Sharing the end (X, X) and leaving it at different slopes: no meeting however close.
  EXPECT_EQ(meetings({at(0, 0), at(22, 2), at(34, 3)}, {{0, 1}, {0, 2}}), 0u);
  // (33, 3) is on the line through (22, 2): the edges overlap, and vertex 1 lies on the longer one.
  EXPECT_EQ(meetings({at(0, 0), at(22, 2), at(33, 3)}, {{0, 1}, {0, 2}}), 2u);
}

}  // namespace
}  // namespace lepp::certify
