// SPDX-License-Identifier: GPL-3.0-or-later
// The check that segment chains cross nowhere (properties/certify/src/chain_embedding.h)
// at its boundaries: closed segments (an end on another edge's interior meets it), a
// shared end (meets elsewhere only along one line the same way), a vertex exactly on
// an edge against one ulp off it, and crossings a few ulps wide at 2^52.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>


#include "chain_embedding.h"
#include "exact.h"

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

// Vertices on edges, as every pair of a vertex and an edge tested in turn finds them: a
// used vertex in the edge's closed box, collinear with it, not one of its ends.
std::vector<std::array<int, 2>> on_edges_by_every_pair(const std::vector<Point>& pts, const std::vector<std::array<int, 2>>& edges,
                                                      const std::vector<char>& used) {
  std::vector<std::array<int, 2>> out;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const Point &a = pts[static_cast<std::size_t>(edges[i][0])], &b = pts[static_cast<std::size_t>(edges[i][1])];
    for (std::size_t v = 0; v < pts.size(); ++v) {
      const Point& p = pts[v];
      if (!used[v] || static_cast<int>(v) == edges[i][0] || static_cast<int>(v) == edges[i][1]) continue;
      if (p.x < std::min(a.x, b.x) || p.x > std::max(a.x, b.x) || p.y < std::min(a.y, b.y) || p.y > std::max(a.y, b.y)) continue;
      if (exact::orient(a, b, p) == 0) out.push_back({static_cast<int>(i), static_cast<int>(v)});
    }
  }
  return out;
}

std::vector<std::array<int, 2>> on_edges(const std::vector<Point>& pts, const std::vector<std::array<int, 2>>& edges,
                                         const std::vector<char>& used) {
  std::vector<std::array<int, 2>> out;
  for (const ChainMeet& m : chain_meetings(pts, edges, used))
    if (m.other < 0) out.push_back({m.edge, m.vertex});
  std::sort(out.begin(), out.end());
  return out;
}

// Points of a small lattice (collinear triples everywhere, vertices at box corners and
// on box sides) joined by short edges (the grid over the edges' boxes) or by long ones
// across the lattice (boxes too large for a grid: box intersection): the same pairs
// as testing every pair, each once.
TEST(ChainEmbedding, VerticesOnEdgesAsEveryPairFindsThem) {
  for (int long_edges : {0, 1}) {
    std::mt19937 rng(20261206 + static_cast<unsigned>(long_edges));
    std::uniform_int_distribution<int> coord(0, 40), step(-2, 2);
    std::vector<Point> pts;
    for (int i = 0; i < 400; ++i) pts.push_back({coord(rng) * 0.25, coord(rng) * 0.25});
    std::vector<std::array<int, 2>> edges;
    for (int i = 0; i < 300; ++i) {
      const int a = static_cast<int>(rng() % pts.size());
      Point far = long_edges ? Point{coord(rng) * 0.25, coord(rng) * 0.25} : Point{pts[static_cast<std::size_t>(a)].x + step(rng) * 0.25, pts[static_cast<std::size_t>(a)].y + step(rng) * 0.25};
      if (far == pts[static_cast<std::size_t>(a)]) continue;
      pts.push_back(far);
      edges.push_back({a, static_cast<int>(pts.size()) - 1});
    }
    std::vector<char> used(pts.size(), 1);
    for (std::size_t v = 0; v < used.size(); v += 7) used[v] = 0;
    const auto expected = on_edges_by_every_pair(pts, edges, used);
    EXPECT_GT(expected.size(), 20u) << long_edges;  // the lattice puts many vertices on edges
    EXPECT_EQ(on_edges(pts, edges, used), expected) << long_edges;
  }
}

// A cluster: every vertex and edge in one cell of the grid but for one short edge far away
// (a mesh refined around vertices ulps apart); the grid hands it to box
// intersection (fuzz_refine's clean-certify-chain-grid-cluster input took 22 s
// there): the same vertices on edges as every pair.
TEST(ChainEmbedding, VerticesOnEdgesInAClusterAsEveryPairFindsThem) {
  std::mt19937 rng(20261207);
  std::uniform_int_distribution<int> coord(0, 30), step(-2, 2);
  std::vector<Point> pts{{1e6, 1e6}, {1e6 + 1, 1e6}};  // a short edge far away: the grid's box is large
  std::vector<std::array<int, 2>> edges{{0, 1}};
  for (int i = 0; i < 300; ++i) pts.push_back({coord(rng) * 0x1p-40, coord(rng) * 0x1p-40});
  for (int i = 0; i < 300; ++i) {
    const int a = 2 + static_cast<int>(rng() % 300);
    const Point& pa = pts[static_cast<std::size_t>(a)];
    const Point far{pa.x + step(rng) * 0x1p-40, pa.y + step(rng) * 0x1p-40};
    if (far == pa) continue;
    pts.push_back(far);
    edges.push_back({a, static_cast<int>(pts.size()) - 1});
  }
  std::vector<char> used(pts.size(), 1);
  const auto expected = on_edges_by_every_pair(pts, edges, used);
  EXPECT_GT(expected.size(), 20u);
  EXPECT_EQ(on_edges(pts, edges, used), expected);
}

}  // namespace
}  // namespace lepp::certify
