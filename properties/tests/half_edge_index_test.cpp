// SPDX-License-Identifier: GPL-3.0-or-later
// The certifier's half-edge index (properties/certify/src/index/index_half_edges.cpp)
// built over ranges: for any thread count the same twins, the same edges in edge-key
// order, the same half-edges per edge by id and the same used vertices, on a grid mesh
// with triangles repeated (edges in three triangles) and removed (boundary edges); and
// the same index as one built the plain way, a map from each edge to its half-edges.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>
#include <stdexcept>

#include "certification.h"
#include "index/index_limits.h"
#include "passes.h"
#include "ranges.h"

namespace lepp::certify {
namespace {

Mesh damaged_grid(int n, std::uint64_t seed) {
  Mesh m;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) m.vertices.push_back({static_cast<double>(i), static_cast<double>(j)});
  auto id = [n](int i, int j) { return j * n + i; };
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  // Vertex ids shuffled, so that a triangle's ends fall in every range of vertices.
  std::mt19937_64 rng(seed);
  std::vector<int> perm(m.vertices.size());
  for (std::size_t v = 0; v < perm.size(); ++v) perm[v] = static_cast<int>(v);
  std::shuffle(perm.begin(), perm.end(), rng);
  std::vector<Point> moved(m.vertices.size());
  for (std::size_t v = 0; v < perm.size(); ++v) moved[static_cast<std::size_t>(perm[v])] = m.vertices[v];
  m.vertices = moved;
  for (Tri& t : m.triangles)
    for (int& v : t) v = perm[static_cast<std::size_t>(v)];
  std::uniform_int_distribution<std::size_t> tri(0, m.triangles.size() - 1);
  for (int k = 0; k < 6; ++k) m.triangles.push_back(m.triangles[tri(rng)]);
  for (int k = 0; k < 6; ++k) m.triangles.erase(m.triangles.begin() + static_cast<std::ptrdiff_t>(tri(rng) % (m.triangles.size() - 1)));
  return m;
}

struct Built {
  std::vector<int> twin, half_begin;
  std::vector<std::array<int, 2>> edges;
  std::vector<std::array<int, 3>> halves;
  std::vector<char> used;
  std::size_t violations = 0;
};

// A certification of `mesh` alone (no input) on `threads` threads, with its triangle
// and half-edge indexes and its adjacency built.
struct Indexed {
  Pslg pslg;
  Options options;
  Report report;
  Certification cert;
  Indexed(const Mesh& mesh, int threads) : options(on_threads(threads)), cert(pslg, mesh, options, report) {
    pass::index_triangles(cert);
    pass::index_half_edges(cert);
    pass::index_adjacency(cert);  // and the used vertices
  }
  static Options on_threads(int threads) {
    Options o;
    o.threads = threads;
    return o;
  }
};

Built build(const Mesh& mesh, int threads) {
  const Indexed indexed(mesh, threads);
  const MeshIndex& ix = indexed.cert.index;
  Built b{{ix.twin.begin(), ix.twin.end()}, ix.half_begin, {}, {}, ix.used, indexed.report.violations.size()};
  ix.each_edge([&b](int x, int y, std::size_t) { b.edges.push_back({x, y}); });
  EXPECT_EQ(b.edges.size(), ix.edge_count);
  for (const MeshIndex::Half& h : ix.halves) b.halves.push_back({h.other, h.h(), h.up()});
  return b;
}

TEST(HalfEdgeIndex, SameForAnyThreadCountInEdgeKeyOrder) {
  const Mesh mesh = damaged_grid(23, 20261206);
  const Built one = build(mesh, 1);
  EXPECT_GT(one.violations, 0u);  // the repeated triangles' edges
  for (std::size_t i = 1; i < one.edges.size(); ++i)
    ASSERT_LT(edge_key(one.edges[i - 1][0], one.edges[i - 1][1]), edge_key(one.edges[i][0], one.edges[i][1])) << i;
  for (std::size_t h = 0; h < one.twin.size(); ++h)
    if (one.twin[h] >= 0) ASSERT_EQ(one.twin[static_cast<std::size_t>(one.twin[h])], static_cast<int>(h)) << h;
  for (int threads : {2, 3, 7}) {
    const Built many = build(mesh, threads);
    EXPECT_EQ(many.twin, one.twin) << threads;
    EXPECT_EQ(many.edges, one.edges) << threads;
    EXPECT_EQ(many.half_begin, one.half_begin) << threads;
    EXPECT_EQ(many.halves, one.halves) << threads;
    EXPECT_EQ(many.used, one.used) << threads;
    EXPECT_EQ(many.violations, one.violations) << threads;
  }
}

// The index against its definition, built the plain way: a map from each edge of a valid
// triangle to its half-edges by id. Twins, -1 and -2 (-1 on an invalid triangle too),
// the used vertices, the edges in key order, each half-edge's way (Half::up, kept so
// that pairing loads no triangle) and every lookup.
TEST(HalfEdgeIndex, SameAsAMapFromEachEdgeToItsHalfEdges) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    Mesh mesh = damaged_grid(17, seed);
    mesh.vertices.push_back({-5, -5});                                          // in no triangle: not used
    mesh.triangles.push_back({0, 1, static_cast<int>(mesh.vertices.size())});  // an id out of range: no half-edges
    for (int threads : {1, 2, 3}) {
      const Indexed indexed(mesh, threads);
      const MeshIndex& ix = indexed.cert.index;
      std::map<std::uint64_t, std::vector<int>> by_edge;
      for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        if (ix.tri_ok[t])
          for (int i = 0; i < 3; ++i) {
            const int h = static_cast<int>(3 * t) + i;
            by_edge[edge_key(ix.from(h), ix.to(h))].push_back(h);
          }
      std::vector<char> used(mesh.vertices.size(), 0);  // in a valid triangle
      for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        if (ix.tri_ok[t])
          for (int v : mesh.triangles[t]) used[static_cast<std::size_t>(v)] = 1;
      EXPECT_EQ(ix.used, used) << threads;
      EXPECT_EQ(used.back(), 0);
      std::vector<int> twin(3 * mesh.triangles.size(), -1);
      std::vector<std::array<int, 2>> edges;
      for (const auto& [key, halves] : by_edge) {
        edges.push_back(edge_ends(key));
        const bool pair = halves.size() == 2 && ix.from(halves[0]) != ix.from(halves[1]);
        for (std::size_t k = 0; k < halves.size(); ++k)
          twin[static_cast<std::size_t>(halves[k])] = pair ? halves[1 - k] : halves.size() == 1 ? -1 : -2;
        const std::array<int, 2> e = edge_ends(key);
        std::vector<int> found;
        for (auto [first, last] = ix.halves_on(e[1], e[0]); first != last; ++first) {
          found.push_back(first->h());
          EXPECT_EQ(first->up(), ix.from(first->h()) < ix.to(first->h())) << first->h();
        }
        EXPECT_EQ(found, halves) << e[0] << "-" << e[1] << ", " << threads << " threads";
      }
      EXPECT_GT(std::count(twin.begin(), twin.end(), -2), 0);  // the repeated triangles' edges
      EXPECT_EQ(std::vector<int>(ix.twin.begin(), ix.twin.end()), twin) << threads;
      std::vector<std::array<int, 2>> each;
      ix.each_edge([&each](int x, int y, std::size_t) { each.push_back({x, y}); });
      EXPECT_EQ(each, edges) << threads;
      EXPECT_EQ(ix.edge_count, edges.size()) << threads;
    }
  }
}

// The vertex adjacency (the smaller neighbours stored, the larger ones read from the
// buckets, built over ranges of smaller ends) against the neighbours of each vertex
// collected from the triangles, and the same arrays for any thread count.
TEST(HalfEdgeIndex, NeighboursAreEachVertexsNeighboursAscending) {
  const Mesh mesh = damaged_grid(13, 7);
  std::vector<int> one_begin, one_lower;
  for (int threads : {1, 2, 3, 7}) {
    const Indexed indexed(mesh, threads);
    const MeshIndex& ix = indexed.cert.index;
    if (threads == 1) {
      one_begin = ix.lower_begin, one_lower = ix.lower;
    } else {
      EXPECT_EQ(ix.lower_begin, one_begin) << threads;
      EXPECT_EQ(ix.lower, one_lower) << threads;
    }
    std::vector<std::set<int>> around(mesh.vertices.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      for (int i = 0; i < 3; ++i) {
        const int h = static_cast<int>(3 * t) + i;
        around[static_cast<std::size_t>(ix.from(h))].insert(ix.to(h));
        around[static_cast<std::size_t>(ix.to(h))].insert(ix.from(h));
      }
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
      const std::vector<int> expected(around[v].begin(), around[v].end());
      EXPECT_EQ(ix.neighbors(static_cast<int>(v)), expected) << v;
      for (std::size_t w = 0; w < mesh.vertices.size(); ++w)
        ASSERT_EQ(ix.adjacent(static_cast<int>(v), static_cast<int>(w)), around[v].count(static_cast<int>(w)) > 0) << v << " " << w;
    }
  }
}

// The passes over the buckets split the vertices where the half-edges split evenly:
// consecutive ranges from 0 to the vertex count, each bucket in one range, and each
// range's half-edges within a bucket's size of an even share.
TEST(HalfEdgeIndex, VertexRangesHoldAboutAsManyHalfEdgesEach) {
  const Mesh mesh = damaged_grid(21, 11);
  for (int threads : {1, 2, 3, 7}) {
    const Indexed indexed(mesh, threads);
    const MeshIndex& ix = indexed.cert.index;
    const std::vector<std::size_t> first = vertex_ranges_by_halves(indexed.cert);
    ASSERT_EQ(first.size(), static_cast<std::size_t>(threads) + 1);
    EXPECT_EQ(first.front(), 0u);
    EXPECT_EQ(first.back(), mesh.vertices.size());
    std::size_t largest_bucket = 0;
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
      largest_bucket = std::max(largest_bucket, static_cast<std::size_t>(ix.half_begin[v + 1] - ix.half_begin[v]));
    const double share = static_cast<double>(ix.halves.size()) / threads;
    for (std::size_t r = 0; r + 1 < first.size(); ++r) {
      ASSERT_LE(first[r], first[r + 1]) << threads;
      const double in_range = ix.half_begin[first[r + 1]] - ix.half_begin[first[r]];
      EXPECT_NEAR(in_range, share, static_cast<double>(largest_bucket)) << "range " << r << " of " << threads;
    }
  }
  // Lower vertices hold more half-edges here (the smaller end of each edge): an even
  // split of the vertices would not be even in half-edges.
  const Indexed two(mesh, 2);
  EXPECT_LT(vertex_ranges_by_halves(two.cert)[1], mesh.vertices.size() / 2);
}

// The 32-bit limit, at its boundary: through the seam with a small limit (the same
// code as the real one), and at the real one without a mesh that large.
TEST(HalfEdgeIndex, MeshesPastTheIdsLimitAreRefusedAtTheBoundary) {
  EXPECT_NO_THROW(check_index_limits(9, 3, 9));  // 9 vertices, 9 half-edges: ids 0..8
  EXPECT_THROW(check_index_limits(10, 3, 9), std::length_error);
  EXPECT_THROW(check_index_limits(9, 4, 9), std::length_error);
  EXPECT_NO_THROW(check_index_limits(9, 3, 11));  // 11 ids hold 3 triangles, not 4
  EXPECT_THROW(check_index_limits(9, 4, 11), std::length_error);
  try {
    check_index_limits(0, 4, 11);
    ADD_FAILURE() << "not refused";
  } catch (const std::length_error& e) {
    EXPECT_STREQ(e.what(), "the mesh has 4 triangles; the certifier numbers their half-edges (3 a triangle) in 32-bit ids, so at most 3 triangles");
  }
  // The real limit: the largest half-edge id 3 t + 2 of the last triangle is INT_MAX - 2.
  EXPECT_NO_THROW(check_index_limits(kMaxIndexIds, 715827882));
  EXPECT_THROW(check_index_limits(kMaxIndexIds, 715827883), std::length_error);
  EXPECT_THROW(check_index_limits(kMaxIndexIds + 1, 0), std::length_error);
  EXPECT_EQ(3 * std::size_t{715827882} - 1, kMaxIndexIds - 2);
}

}  // namespace
}  // namespace lepp::certify
