// SPDX-License-Identifier: GPL-3.0-or-later
// The report is the same for any thread count (Options::threads, docs/CERTIFIER.md
// "Threads"): every pass that splits its work into ranges merges them in range order,
// so the violations, their order, the per-kind listing cap and every count agree with
// one thread's. Checked on a refined mesh broken in many places at once (violations of
// several kinds spread over every range), and on the mesh unbroken; the JSON too.
#include <gtest/gtest.h>

#include <random>
#include <utility>

#include "cgal_mesh.h"
#include "lepp/certify.h"
#include "lepp/certify_json.h"
#include "lepp/validate.h"
#include "test_pslgs.h"

namespace lepp {
namespace {

// Everything the report says, as text: its formatted form, then each violation's
// fields (format_report lists at most the cap) and the counters behind the statistics.
std::string everything(const certify::Report& r) {
  std::string s = certify::format_report(r);
  for (const certify::Violation& v : r.violations) s += std::string(certify::to_string(v.reason)) + ": " + v.message + "\n";
  for (std::size_t n : r.count_by_reason) s += std::to_string(n) + " ";
  s += "\n" + std::to_string(r.stats.delaunay_edges_checked) + " " + std::to_string(r.stats.cocircular_edges) + " " +
       std::to_string(r.stats.terminal_pairs_checked) + " " + std::to_string(r.stats.avg_lepp_size) + " " +
       std::to_string(r.stats.min_angle_deg);
  return s;
}

// A CGAL-refined mesh, then `breaks` random damages: a triangle reversed,
// a diagonal flipped (not locally Delaunay, or a constrained edge lost), a vertex
// nudged, a triangle's corner made out of range.
Mesh broken_mesh(const Mesh& good, int breaks, std::uint64_t seed) {
  Mesh m = good;
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::size_t> tri(0, m.triangles.size() - 1), vert(0, m.vertices.size() - 1);
  for (int i = 0; i < breaks; ++i) {
    Tri& t = m.triangles[tri(rng)];
    switch (i % 4) {
      case 0: std::swap(t[0], t[1]); break;                                  // clockwise
      case 1: t[2] = t[0] == 0 ? 1 : 0; break;                               // a corner moved elsewhere
      case 2: m.vertices[vert(rng)].x += 0.37; break;                        // a vertex nudged
      default: t[1] = static_cast<int>(m.vertices.size()) + i; break;        // out of range
    }
  }
  return m;
}

// A square whose sides carry 25 points each, with the square_with_hole's hole shape
// left out: CGAL refines it to a few hundred triangles.
Pslg finely_sampled_square() {
  Pslg p;
  const int per_side = 25;
  for (int side = 0; side < 4; ++side)
    for (int i = 0; i < per_side; ++i) {
      const double t = static_cast<double>(i) / per_side;
      const Point corner[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      const Point a = corner[side], b = corner[(side + 1) % 4];
      p.vertices.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
    }
  const int n = static_cast<int>(p.vertices.size());
  for (int i = 0; i < n; ++i) p.segments.push_back({i, (i + 1) % n});
  return p;
}

TEST(CertifyThreads, SameReportForAnyThreadCount) {
  const Pslg pslg = test::validated(finely_sampled_square());
  const Mesh good = test::as_read(test::cgal_refined(pslg, 0.1));
  ASSERT_GT(good.triangles.size(), 40u);
  for (int breaks : {0, 7, 40}) {
    const Mesh mesh = broken_mesh(good, breaks, 20261206 + static_cast<std::uint64_t>(breaks));
    certify::Options one;
    one.min_angle_deg = 25;  // some of CGAL's triangles are below: angle violations too
    one.max_listed_per_reason = 3;  // the cap applies across ranges
    const certify::Report single = certify::certify(pslg, mesh, one);
    if (breaks > 0) EXPECT_FALSE(single.certified());
    for (int threads : {2, 3, 7, 0}) {
      certify::Options many = one;
      many.threads = threads;
      EXPECT_EQ(everything(certify::certify(pslg, mesh, many)), everything(single)) << breaks << " breaks, " << threads << " threads";
    }
  }
}

// Damages the passes made parallel for issue 40 see: triangles repeated (edges in three
// triangles, and the copies' edges traversed the same way), triangles removed (gaps on no
// segment), an exact copy of a used vertex given to a triangle (duplicate vertices, and
// the vertex it left unused), a vertex moved onto the square's bottom side (a chain edge
// with a vertex on it), and vertices moved to make skinny triangles.
Mesh overlapped_mesh(const Mesh& good, int breaks, std::uint64_t seed) {
  Mesh m = good;
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::size_t> tri(0, m.triangles.size() - 1);
  for (int i = 0; i < breaks; ++i) {
    const std::size_t t = tri(rng);
    switch (i % 5) {
      case 0: m.triangles.push_back(m.triangles[t]); break;
      case 1: m.triangles.erase(m.triangles.begin() + static_cast<std::ptrdiff_t>(t)); break;
      case 2:
        m.vertices.push_back(m.vertices[static_cast<std::size_t>(m.triangles[t][0])]);
        m.triangles[t][0] = static_cast<int>(m.vertices.size()) - 1;
        break;
      case 3: m.vertices[static_cast<std::size_t>(m.triangles[t][1])].y = 0; break;
      default: m.vertices[static_cast<std::size_t>(m.triangles[t][2])].x += 0.01; break;
    }
  }
  return m;
}

TEST(CertifyThreads, SameReportForOverlapsGapsDuplicatesAndVerticesOnChains) {
  const Pslg pslg = test::validated(finely_sampled_square());
  const Mesh good = test::as_read(test::cgal_refined(pslg, 0.1));
  for (int breaks : {5, 30}) {
    const Mesh mesh = overlapped_mesh(good, breaks, 20261207 + static_cast<std::uint64_t>(breaks));
    certify::Options one;
    one.min_angle_deg = 25;
    one.max_listed_per_reason = 4;
    one.max_area = 0.003;  // some triangles above it: the size-bound pass's ranges too
    const certify::Report single = certify::certify(pslg, mesh, one);
    if (breaks == 30)  // every kind (5 breaks: a few, in fewer ranges)
      for (certify::Reason r : {certify::Reason::EdgeOverused, certify::Reason::BoundaryNotOnDomainBoundary, certify::Reason::DuplicateMeshVertex,
                                certify::Reason::ChainEdgesMeet, certify::Reason::AngleBelowTheta, certify::Reason::AreaAboveBound})
        EXPECT_TRUE(single.has(r)) << breaks << " breaks: no " << certify::to_string(r) << "\n" << certify::format_report(single);
    const std::string json = certify::json_report(single, 1000).dump(2);
    for (int threads : {2, 3, 7, 0}) {
      certify::Options many = one;
      many.threads = threads;
      const certify::Report r = certify::certify(pslg, mesh, many);
      EXPECT_EQ(everything(r), everything(single)) << breaks << " breaks, " << threads << " threads";
      EXPECT_EQ(certify::json_report(r, 1000).dump(2), json) << breaks << " breaks, " << threads << " threads";
    }
  }
}

}  // namespace
}  // namespace lepp
