// SPDX-License-Identifier: GPL-3.0-or-later
// TriMesh::take_canonical_mesh (canonical_mesh.cpp) on one thread and split on two
// gives canonicalize's mesh: the same vertices, triangles and constrained edges,
// on meshes of 1 to thousands of triangles, with a bucket larger than the insertion
// sort's 16 and one spanning the split.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>
#include <vector>

#include "cdt_build.h"
#include "lepp/mesh.h"
#include "tri_mesh.h"

namespace lepp::fast {
namespace {

bool same_edges(const std::vector<ConstrainedEdge>& x, const std::vector<ConstrainedEdge>& y) {
  return std::equal(x.begin(), x.end(), y.begin(), y.end(), [](const ConstrainedEdge& a, const ConstrainedEdge& b) {
    return std::tie(a.a, a.b, a.segment) == std::tie(b.a, b.b, b.segment);
  });
}

// The canonical mesh of the PSLG's CDT made three ways: canonicalize of to_mesh
// (the oracle), take_canonical_mesh on one thread, and split on two from
// `split_from` triangles. Returns the oracle's triangle count.
std::size_t expect_same_three_ways(const Pslg& pslg, std::size_t split_from, const char* what) {
  const SegmentMembership mem = make_membership(pslg);
  const TriMesh cdt = build_initial_cdt(pslg, mem, 0, 0);
  Mesh oracle = cdt.to_mesh(mem);
  canonicalize(oracle);
  TriMesh one = cdt, two = cdt;
  const Mesh a = one.take_canonical_mesh(mem, 1), b = two.take_canonical_mesh(mem, 2, split_from);
  for (const Mesh* m : {&a, &b}) {
    const char* which = m == &a ? "one thread" : "two threads";
    EXPECT_EQ(m->vertices.size(), oracle.vertices.size()) << what << ", " << which;
    EXPECT_EQ(m->input_vertices, oracle.input_vertices) << what << ", " << which;
    EXPECT_EQ(m->triangles, oracle.triangles) << what << ", " << which;
    EXPECT_TRUE(same_edges(m->constrained_edges, oracle.constrained_edges)) << what << ", " << which;
  }
  EXPECT_TRUE(one.tris.empty() && one.pts.empty() && two.tris.empty() && two.pts.empty()) << what;
  return oracle.triangles.size();
}

// n points on a circle (its boundary segments) and `inside` random points within.
Pslg disc(int n, int inside, unsigned seed) {
  Pslg p;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * M_PI * k / n;
    p.vertices.push_back({std::cos(t), std::sin(t)});
    p.segments.push_back({k, (k + 1) % n});
  }
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.6, 0.6);
  for (int k = 0; k < inside; ++k) p.vertices.push_back({u(rng), u(rng)});
  // A crack: a constrained edge inside, between two of the inner points.
  if (inside >= 2) p.segments.push_back({n, n + 1});
  return p;
}

TEST(CanonicalMesh, TwoThreadsGiveCanonicalizesMesh) {
  // Splits of 1, 2, 3 ... triangles (h = 0 and 1 included), then thousands.
  for (int n = 3; n <= 8; ++n) expect_same_three_ways(disc(n, 0, 1), 0, "small disc");
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const std::size_t triangles = expect_same_three_ways(disc(200, 3000, seed), 0, "disc of 3,200 points");
    EXPECT_GT(triangles, 6000u);
  }
  // Below split_from the two-thread call takes the one-thread path: the same mesh too.
  expect_same_three_ways(disc(200, 3000, 4), 1 << 20, "disc below split_from");
}

// A fan whose centre (vertex 0, the smallest id) starts every triangle: one bucket
// of n triangles, sorted by std::sort past 16, and the split falls inside it.
TEST(CanonicalMesh, OneLargeBucketAcrossTheSplit) {
  for (int n : {3, 17, 40, 301}) {
    Pslg fan;
    fan.vertices.push_back({0, 0});
    for (int k = 0; k < n; ++k) {
      const double t = 2 * M_PI * k / n;
      fan.vertices.push_back({std::cos(t), std::sin(t)});
      fan.segments.push_back({1 + k, 1 + (k + 1) % n});
    }
    EXPECT_EQ(expect_same_three_ways(fan, 0, "fan"), static_cast<std::size_t>(n)) << n;
  }
}

}  // namespace
}  // namespace lepp::fast
