// SPDX-License-Identifier: GPL-3.0-or-later
// The conformance replay with size bounds (ConformanceOptions::max_area and
// region_area_bounds, docs/CONFORMANCE.md): a triangle too big for the bound of
// its region is bad, as in the engines. Traces of both engines made with
// --max-area, --region-areas or both conform when the check knows the bounds,
// and are rejected when it does not (so the test can fail), on irregular input
// and on a lattice box whose cocircular cells the replay searches.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lepp/audit/judge/conformance.h"
#include "lepp/fast.h"
#include "lepp/gen_lattice_box.h"
#include "lepp/gen_symmetry.h"
#include "lepp/io.h"
#include "lepp/reference.h"
#include "lepp/validate.h"

namespace lepp::audit {
namespace {

struct Bounds {
  double max_area = 0;
  bool regions = false;
};

std::vector<Point> trace_of(const Pslg& p, bool fast_engine, Method m, double theta, Bounds b) {
  RefineOptions o;
  o.min_angle_deg = theta;
  o.method = m;
  o.max_area = b.max_area;
  o.region_area_bounds = b.regions;
  o.trace = true;
  const RefineResult r = fast_engine ? fast::refine(p, o) : reference::refine(p, o);
  EXPECT_EQ(r.outcome, Outcome::Converged);
  std::vector<Point> out;
  for (const TraceStep& s : r.trace) out.push_back(s.point);
  return out;
}

ConformanceReport check(const Pslg& p, const std::vector<Point>& trace, Method m, double theta, Bounds b) {
  ConformanceOptions o;
  o.method = m;
  o.min_angle_deg = theta;
  o.max_area = b.max_area;
  o.region_area_bounds = b.regions;
  return check_conformance(p, trace, o);
}

void expect_conforms_only_with_the_bounds(const Pslg& p, Method m, double theta, Bounds b) {
  for (bool fast_engine : {false, true}) {
    SCOPED_TRACE(testing::Message() << (fast_engine ? "fast" : "reference") << " engine, max_area " << b.max_area
                                    << ", region bounds " << b.regions);
    const std::vector<Point> trace = trace_of(p, fast_engine, m, theta, b);
    const ConformanceReport with = check(p, trace, m, theta, b);
    EXPECT_TRUE(with.conforms) << describe(with);
    // The check without the bounds: the points inserted for triangles that are
    // only too big are no choice.
    const ConformanceReport without = check(p, trace, m, theta, Bounds{});
    EXPECT_FALSE(without.conforms);
    if (b.max_area > 0 && b.regions) {  // either bound alone is not enough either
      EXPECT_FALSE(check(p, trace, m, theta, Bounds{b.max_area, false}).conforms);
      EXPECT_FALSE(check(p, trace, m, theta, Bounds{0, true}).conforms);
    }
  }
}

Pslg region_areas_poly() {
  std::vector<std::string> warnings;
  return validate(read_poly(LEPP_SOURCE_DIR "/corpus/triangle-formats/region-areas.poly"), warnings);
}

TEST(ConformanceSizeBound, TracesMadeWithRegionBoundsConformWithThem) {
  const Pslg p = region_areas_poly();
  expect_conforms_only_with_the_bounds(p, Method::Centroid, 30, {0, true});
  expect_conforms_only_with_the_bounds(p, Method::Midpoint, 20, {0, true});
}

TEST(ConformanceSizeBound, TracesMadeWithTheGlobalBoundConformWithIt) {
  const Pslg p = region_areas_poly();
  expect_conforms_only_with_the_bounds(p, Method::Centroid, 30, {0.2, false});
  expect_conforms_only_with_the_bounds(p, Method::Midpoint, 20, {0.2, false});
}

TEST(ConformanceSizeBound, TracesMadeWithBothBoundsConformWithBoth) {
  // 0.2 is below region 2's bound (0.5) and bounds region 3 (none of its own):
  // there the global bound decides, elsewhere the region's.
  expect_conforms_only_with_the_bounds(region_areas_poly(), Method::Centroid, 30, {0.2, true});
}

TEST(ConformanceSizeBound, RegionBoundsOnCocircularLatticeCells) {
  // An 8 x 3 lattice box (its boundary's lattice points): the squares of its
  // CDT are cells of four cocircular points, split by a segment at x = 4 into
  // two regions, bounds 0.3 on the left and 0.2 on the right. The engines run on
  // it turned by 90 degrees (their points turned back) triangulate cells
  // otherwise than the replay: it follows them through the cells' other
  // triangulations, whose triangles must carry their region's bound.
  Pslg box = gen::lattice_box(8, 3);
  const int bottom = 4, top = 8 + 3 + 4;  // (4, 0) and (4, 3) in lattice_box's ring order
  ASSERT_EQ(box.vertices[bottom].x, 4);
  ASSERT_EQ(box.vertices[bottom].y, 0);
  ASSERT_EQ(box.vertices[top].x, 4);
  ASSERT_EQ(box.vertices[top].y, 3);
  box.segments.push_back({bottom, top, 2});
  box.regions = {{{0.5, 0.5}, 1, 0.3}, {{7.5, 0.5}, 2, 0.2}};
  std::vector<std::string> warnings;
  const Pslg p = validate(box, warnings);
  const gen::LatticeSymmetry plus90{1, false};
  const Pslg turned = validate(plus90.apply(box), warnings);
  const Bounds regions{0, true};
  for (bool fast_engine : {false, true}) {
    SCOPED_TRACE(fast_engine ? "fast" : "reference");
    std::vector<Point> trace;
    for (const Point& q : trace_of(turned, fast_engine, Method::Centroid, 25, regions)) trace.push_back(plus90.undo(q));
    const ConformanceReport with = check(p, trace, Method::Centroid, 25, regions);
    EXPECT_TRUE(with.conforms) << describe(with);
    EXPECT_GT(with.cocircular_flips, 2) << "the cells' other triangulations were not needed";
    EXPECT_FALSE(check(p, trace, Method::Centroid, 25, Bounds{}).conforms);
    // Unturned too: the replay's own triangulation of the cells.
    EXPECT_TRUE(check(p, trace_of(p, fast_engine, Method::Centroid, 25, regions), Method::Centroid, 25, regions).conforms);
  }
}

}  // namespace
}  // namespace lepp::audit
