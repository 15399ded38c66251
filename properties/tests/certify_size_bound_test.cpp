// SPDX-License-Identifier: GPL-3.0-or-later
// The certifier's size bounds (docs/CERTIFIER.md section 7): --max-area and
// --region-areas for any mesher. lepp's meshes made with the bounds certify with
// them, made without they are rejected; the area is decided exactly at the bound;
// regions are flooded on the mesh, later ones overwriting earlier ones, and a
// region point on a segment, on a vertex or outside applies to nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "certify_test_support.h"
#include "lepp/certify.h"
#include "lepp/fast.h"
#include "lepp/io.h"
#include "lepp/reference.h"
#include "lepp/validate.h"

namespace lepp {
namespace {

using certify::Reason;
using certify::RegionPlace;
using test::expect_certified;
using test::expect_rejected_for;

certify::Report certify_with(const Pslg& p, const Mesh& m, double max_area, bool regions, double theta = 0) {
  certify::Options o;
  o.min_angle_deg = theta;
  o.max_area = max_area;
  o.region_area_bounds = regions;
  return certify::certify(p, m, o);
}

Pslg region_areas_poly() {
  std::vector<std::string> warnings;
  return validate(read_poly(LEPP_SOURCE_DIR "/corpus/triangle-formats/region-areas.poly"), warnings);
}

RefineResult refine_with(const Pslg& p, bool fast_engine, double max_area, bool regions) {
  RefineOptions o;
  o.min_angle_deg = 30;
  o.max_area = max_area;
  o.region_area_bounds = regions;
  return fast_engine ? fast::refine(p, o) : reference::refine(p, o);
}

// --- lepp's meshes ----------------------------------------------------------

TEST(CertifySizeBound, LeppMeshesWithTheBoundsCertifyWithThem) {
  const Pslg p = region_areas_poly();
  for (bool fast_engine : {false, true}) {
    SCOPED_TRACE(fast_engine ? "fast" : "reference");
    struct Case {
      double max_area;
      bool regions;
    };
    for (const Case c : {Case{0, true}, Case{0.2, false}, Case{0.2, true}}) {
      SCOPED_TRACE(testing::Message() << "max_area " << c.max_area << " regions " << c.regions);
      const RefineResult r = refine_with(p, fast_engine, c.max_area, c.regions);
      ASSERT_EQ(r.outcome, Outcome::Converged);
      const certify::Report report = certify_with(p, r.mesh, c.max_area, c.regions, 30);
      expect_certified(report);
      // Every triangle has a region here; region 3's bound is none.
      EXPECT_EQ(report.area_checked, c.max_area > 0 ? r.mesh.triangles.size() : r.mesh.triangles.size() - report.region_triangles[3]);
      if (c.regions) {
        // Region 0 is overwritten by region 1, region 3 has no bound, region 4 is in the hole.
        ASSERT_EQ(report.region_places.size(), 5u);
        EXPECT_EQ(report.region_places[4], RegionPlace::InHole);
        EXPECT_EQ(report.region_triangles[0], 0u);
        EXPECT_GT(report.region_triangles[1], 0u);
        EXPECT_GT(report.region_triangles[2], 0u);
        EXPECT_GT(report.region_triangles[3], 0u);
        EXPECT_EQ(report.region_triangles[4], 0u);
      }
    }
  }
}

TEST(CertifySizeBound, LeppMeshesWithoutTheBoundsAreRejected) {
  const Pslg p = region_areas_poly();
  for (bool fast_engine : {false, true}) {
    SCOPED_TRACE(fast_engine ? "fast" : "reference");
    const Mesh plain = refine_with(p, fast_engine, 0, false).mesh;
    expect_certified(certify_with(p, plain, 0, false, 30));  // fine without bounds
    // A region bound: the violations name the region whose bound applies.
    const certify::Report regional = certify_with(p, plain, 0, true, 30);
    expect_rejected_for(regional, Reason::AreaAboveBound);
    EXPECT_EQ(test::total(regional), regional.count(Reason::AreaAboveBound));
    for (const certify::Violation& v : regional.violations) {
      EXPECT_TRUE(v.region == 1 || v.region == 2) << v.message;  // 0 is overwritten, 3 has no bound
      EXPECT_NE(v.message.find("region " + std::to_string(v.region)), std::string::npos) << v.message;
      ASSERT_EQ(v.triangles.size(), 1u);
      EXPECT_EQ(regional.triangle_region[static_cast<std::size_t>(v.triangles[0])], v.region);
    }
    // The global bound alone: no region named.
    const certify::Report global = certify_with(p, plain, 0.2, false, 30);
    expect_rejected_for(global, Reason::AreaAboveBound);
    EXPECT_EQ(global.violations.front().region, -1);
    EXPECT_NE(global.violations.front().message.find("global bound 0.2"), std::string::npos) << global.violations.front().message;
    // A mesh made with the global bound only, checked with the regions' too (smaller): rejected.
    const Mesh global_only = refine_with(p, fast_engine, 0.2, false).mesh;
    expect_rejected_for(certify_with(p, global_only, 0.2, true, 30), Reason::AreaAboveBound);
  }
}

// --- Hand-made meshes ---------------------------------------------------------

// A triangle as its own PSLG and mesh.
test::MeshedPslg one_triangle(Point a, Point b, Point c) {
  test::MeshedPslg w;
  w.pslg.vertices = {a, b, c};
  w.pslg.segments = {{0, 1, 0}, {1, 2, 0}, {2, 0, 0}};
  w.mesh.vertices = w.pslg.vertices;
  w.mesh.input_vertices = 3;
  w.mesh.triangles = {{0, 1, 2}};
  return w;
}

TEST(CertifySizeBound, AreaExactlyTheBoundPassesAndABitMoreFails) {
  // Doubled area exactly 1: the bound 0.5 holds, one ulp less does not.
  const test::MeshedPslg exact = one_triangle({0, 0}, {1, 0}, {1, 1});
  expect_certified(certify_with(exact.pslg, exact.mesh, 0.5, false));
  test::expect_rejected_only_for(certify_with(exact.pslg, exact.mesh, std::nextafter(0.5, 0.0), false), Reason::AreaAboveBound);
  // Doubled area 1 + 2^-60 (less than an ulp of 1 above it): in doubles the
  // determinant rounds to exactly 1, so only the exact test sees it above 0.5.
  const double tiny = std::ldexp(1.0, -60);
  const test::MeshedPslg above = one_triangle({0, 0}, {1, -tiny}, {1, 1});
  volatile double bx = 1, by = -tiny, cx = 1, cy = 1;
  ASSERT_EQ(bx * cy - by * cx, 1.0) << "the case must need the exact test";
  test::expect_rejected_only_for(certify_with(above.pslg, above.mesh, 0.5, false), Reason::AreaAboveBound);
  expect_certified(certify_with(above.pslg, above.mesh, 0.5 + std::ldexp(1.0, -52), false));
  // The region bound is decided the same way.
  test::MeshedPslg regional = above;
  regional.pslg.regions = {{{0.9, 0.5}, 0, 0.5}};
  const certify::Report r = certify_with(regional.pslg, regional.mesh, 0, true);
  test::expect_rejected_only_for(r, Reason::AreaAboveBound);
  EXPECT_EQ(r.violations.front().region, 0);
}

// Two unit squares side by side, [0,1]x[0,1] and [1,2]x[0,1], split by the segment
// x = 1; each square is two triangles of area 1/2 (diagonals (0,0)-(1,1) and (1,0)-(2,1)).
test::MeshedPslg two_squares(std::vector<Region> regions) {
  test::MeshedPslg w;
  w.pslg.vertices = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {0, 1}};
  w.pslg.segments = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}, {3, 4, 0}, {4, 5, 0}, {5, 0, 0}, {1, 4, 0}};
  w.pslg.regions = std::move(regions);
  w.mesh.vertices = w.pslg.vertices;
  w.mesh.input_vertices = 6;
  w.mesh.triangles = {{0, 1, 4}, {0, 4, 5}, {1, 2, 3}, {1, 3, 4}};
  return w;
}

TEST(CertifySizeBound, LaterRegionsOverwriteEarlierOnes) {
  // Regions 0 and 1 both flood the left square; region 1 comes later and wins.
  // Region 0's point lies on the left square's diagonal (an unconstrained edge): it floods.
  const Region small{{0.5, 0.5}, 0, 0.1}, large{{0.25, 0.75}, 0, 1}, right{{1.5, 0.25}, 0, 0.6};
  const test::MeshedPslg later_large = two_squares({small, large, right});
  const certify::Report ok = certify_with(later_large.pslg, later_large.mesh, 0, true);
  expect_certified(ok);
  EXPECT_EQ(ok.triangle_region, (std::vector<int>{1, 1, 2, 2}));
  EXPECT_EQ(ok.region_triangles, (std::vector<std::size_t>{0, 2, 2}));
  EXPECT_EQ(ok.area_checked, 4u);
  // The other order: the small bound wins on the left, both left triangles fail.
  const test::MeshedPslg later_small = two_squares({large, small, right});
  const certify::Report bad = certify_with(later_small.pslg, later_small.mesh, 0, true);
  expect_rejected_for(bad, Reason::AreaAboveBound);
  EXPECT_EQ(bad.count(Reason::AreaAboveBound), 2u);
  EXPECT_EQ(bad.triangle_region, (std::vector<int>{1, 1, 2, 2}));
  for (const certify::Violation& v : bad.violations) EXPECT_EQ(v.region, 1) << v.message;
  // With a global bound too, the smaller applies: 0.4 < 0.6 on the right.
  const certify::Report both = certify_with(later_large.pslg, later_large.mesh, 0.4, true);
  EXPECT_EQ(both.count(Reason::AreaAboveBound), 4u) << certify::format_report(both);
  // Region 1's bound (1) is larger than 0.4: the global bound is named.
  EXPECT_NE(both.violations.front().message.find("global bound 0.4"), std::string::npos) << both.violations.front().message;
}

TEST(CertifySizeBound, RegionPointsOnASegmentAVertexOrOutsideApplyToNothing) {
  const Region on_segment{{1, 0.5}, 0, 0.01}, on_vertex{{1, 1}, 0, 0.01}, on_boundary{{0, 0.5}, 0, 0.01},
      outside{{3, 3}, 0, 0.01};
  const test::MeshedPslg w = two_squares({on_segment, on_vertex, on_boundary, outside});
  const certify::Report r = certify_with(w.pslg, w.mesh, 0, true);
  expect_certified(r);
  EXPECT_EQ(r.region_places, (std::vector<RegionPlace>{RegionPlace::OnSegment, RegionPlace::OnVertex, RegionPlace::OnSegment,
                                                        RegionPlace::Outside}));
  EXPECT_EQ(r.region_triangles, (std::vector<std::size_t>{0, 0, 0, 0}));
  EXPECT_EQ(r.triangle_region, (std::vector<int>{-1, -1, -1, -1}));
  EXPECT_EQ(r.area_checked, 0u);
  // The same bound from a point inside floods (so the test above can fail).
  const test::MeshedPslg inside = two_squares({{{1.5, 0.5}, 0, 0.01}});
  EXPECT_EQ(certify_with(inside.pslg, inside.mesh, 0, true).count(Reason::AreaAboveBound), 2u);
}

TEST(CertifySizeBound, ARegionPointAtAChainVertexRoundedOffTheSegmentFloodsItsOwnSide) {
  // Segment A-B inside a kite A C B D; its chain has the Steiner vertex P, the
  // rounded point a third of the way, off the line by rounding. A region point
  // exactly at P lies on one side of the segment (the input says which, exactly):
  // it floods that side only, though the mesh has it on the chain.
  const Point A{0, 0}, B{1, 0.1}, C{0.5, 1}, D{0.5, -1}, P{1.0 / 3, 0.1 / 3};
  test::MeshedPslg w;
  w.pslg.vertices = {A, B, C, D};
  w.pslg.segments = {{0, 1, 0}, {0, 2, 0}, {2, 1, 0}, {0, 3, 0}, {3, 1, 0}};
  w.pslg.regions = {{P, 0, 1e-6}};
  w.mesh.vertices = {A, B, C, D, P};
  w.mesh.input_vertices = 4;
  w.mesh.triangles = {{0, 4, 2}, {4, 1, 2}, {0, 3, 4}, {4, 3, 1}};  // above: 0, 1; below: 2, 3
  const double side = std::fma(-B.y, P.x, P.y);  // cross(B - A, P - A) with A = 0, B.x = 1: one rounding, exact sign
  ASSERT_NE(side, 0) << "P must be off the segment for this case";
  const certify::Report r = certify_with(w.pslg, w.mesh, 0, true);
  ASSERT_EQ(r.region_places, (std::vector<RegionPlace>{RegionPlace::Floods}));
  const std::vector<int> expected = side > 0 ? std::vector<int>{0, 0, -1, -1} : std::vector<int>{-1, -1, 0, 0};
  EXPECT_EQ(r.triangle_region, expected) << certify::format_report(r);
  EXPECT_EQ(r.count(Reason::AreaAboveBound), 2u) << certify::format_report(r);
  EXPECT_EQ(test::total(r), 2u) << certify::format_report(r);
}

TEST(CertifySizeBound, ViolationsAreCappedPerKindAndAllCounted) {
  const Pslg p = region_areas_poly();
  const Mesh plain = refine_with(p, true, 0, false).mesh;
  certify::Options o;
  o.max_area = 0.01;
  o.max_listed_per_reason = 3;
  const certify::Report r = certify::certify(p, plain, o);
  EXPECT_EQ(r.count(Reason::AreaAboveBound), plain.triangles.size());
  EXPECT_EQ(test::messages(r, Reason::AreaAboveBound).size(), 3u);
  const std::string text = certify::format_report(r);
  EXPECT_NE(text.find("size bound: " + std::to_string(plain.triangles.size()) + " triangles checked, area <= 0.01 everywhere"),
            std::string::npos)
      << text;
}

TEST(CertifySizeBound, NoBoundAsked_NothingChecked) {
  const Pslg p = region_areas_poly();
  const Mesh plain = refine_with(p, true, 0, false).mesh;
  const certify::Report r = certify_with(p, plain, 0, false);
  expect_certified(r);
  EXPECT_EQ(r.area_checked, 0u);
  EXPECT_TRUE(r.region_places.empty());
  EXPECT_EQ(certify::format_report(r).find("size bound"), std::string::npos);
}

}  // namespace
}  // namespace lepp
