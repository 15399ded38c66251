// SPDX-License-Identifier: GPL-3.0-or-later
// Region area bounds (Triangle's -a with no number; RefineOptions::region_area_bounds):
// both engines, checked against regions computed here from the output mesh alone
// (flooded from the region points across its unconstrained edges, in file order,
// later regions overwriting), identical meshes, certified, minimum angle kept.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstdlib>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <fmt/format.h>

#include "lepp/certify.h"
#include "lepp/fast.h"
#include "lepp/reference.h"
#include "lepp/validate.h"
#include "mesh_invariants.h"
#include "random_pslg.h"
#include "result_diff.h"

namespace lepp {
namespace {

using impl_test::difference;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Q = CGAL::Exact_rational;

const int fixed_seed = (setenv("RC_PARAMS", "seed=20261127", 0), 0);

K::Point_2 kp(const Point& p) { return {p.x, p.y}; }

// The region of every output triangle (0 none, k + 1 region k), from the mesh
// alone: each region point, in order, seeds the triangles that hold it strictly
// inside or on an unconstrained edge (on a constrained edge or a vertex: none)
// and floods across unconstrained edges, overwriting earlier regions.
std::vector<int> regions_of(const Pslg& pslg, const Mesh& mesh) {
  std::map<std::pair<int, int>, std::vector<int>> by_edge;
  auto key = [](int a, int b) { return a < b ? std::make_pair(a, b) : std::make_pair(b, a); };
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i)
      by_edge[key(mesh.triangles[t][static_cast<std::size_t>(i)], mesh.triangles[t][static_cast<std::size_t>((i + 1) % 3)])]
          .push_back(static_cast<int>(t));
  std::map<std::pair<int, int>, bool> constrained;
  for (const ConstrainedEdge& e : mesh.constrained_edges) constrained[key(e.a, e.b)] = true;
  auto pt = [&](int v) { return kp(mesh.vertices[static_cast<std::size_t>(v)]); };

  std::vector<int> region(mesh.triangles.size(), 0);
  for (std::size_t r = 0; r < pslg.regions.size(); ++r) {
    const K::Point_2 at = kp(pslg.regions[r].at);
    std::vector<int> todo;
    std::vector<char> seen(mesh.triangles.size(), 0);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const Tri& f = mesh.triangles[t];
      int zeros = 0, negative = 0, zero_edge = -1;
      for (int i = 0; i < 3; ++i) {
        auto o = CGAL::orientation(pt(f[static_cast<std::size_t>(i)]), pt(f[static_cast<std::size_t>((i + 1) % 3)]), at);
        if (o == CGAL::NEGATIVE) ++negative;
        if (o == CGAL::ZERO) ++zeros, zero_edge = i;
      }
      if (negative > 0 || zeros > 1) continue;
      if (zeros == 1 && constrained.count(key(f[static_cast<std::size_t>(zero_edge)], f[static_cast<std::size_t>((zero_edge + 1) % 3)])))
        continue;
      todo.push_back(static_cast<int>(t)), seen[t] = 1;
    }
    while (!todo.empty()) {
      const int t = todo.back();
      todo.pop_back();
      region[static_cast<std::size_t>(t)] = static_cast<int>(r) + 1;
      const Tri& f = mesh.triangles[static_cast<std::size_t>(t)];
      for (int i = 0; i < 3; ++i) {
        auto e = key(f[static_cast<std::size_t>(i)], f[static_cast<std::size_t>((i + 1) % 3)]);
        if (constrained.count(e)) continue;
        for (int u : by_edge[e])
          if (!seen[static_cast<std::size_t>(u)]) seen[static_cast<std::size_t>(u)] = 1, todo.push_back(u);
      }
    }
  }
  return region;
}

// Triangles larger than the bound of their region (the smaller of the region's
// and max_area; max_area alone outside regions), exactly: |cross| > 2 bound.
std::vector<std::string> region_violations(const Pslg& pslg, const Mesh& mesh, double max_area) {
  std::vector<std::string> out;
  const std::vector<int> region = regions_of(pslg, mesh);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    double bound = max_area;
    if (region[t] > 0) {
      const double b = pslg.regions[static_cast<std::size_t>(region[t] - 1)].max_area;
      if (b > 0 && (bound <= 0 || b < bound)) bound = b;
    }
    if (bound <= 0) continue;
    const Tri& f = mesh.triangles[t];
    const Point &a = mesh.vertices[static_cast<std::size_t>(f[0])], &b = mesh.vertices[static_cast<std::size_t>(f[1])],
                &c = mesh.vertices[static_cast<std::size_t>(f[2])];
    Q cross = (Q(b.x) - Q(a.x)) * (Q(c.y) - Q(a.y)) - (Q(b.y) - Q(a.y)) * (Q(c.x) - Q(a.x));
    if (CGAL::abs(cross) > Q(2) * Q(bound))
      out.push_back(fmt::format("triangle {} of region {} larger than {}", impl_test::tri(f), region[t], bound));
  }
  return out;
}

// Three parts side by side, split by two interior segments, a square hole in the
// middle one; irregular coordinates (no four cocircular points).
Pslg three_parts(std::vector<Region> regions) {
  Pslg p;
  p.vertices = {{0, 0},       {4.1, 0.1}, {8.2, 0.2}, {12.1, 0.3}, {12.4, 6.2}, {8.3, 6.1}, {4.0, 6.0},
                {-0.3, 5.9},  {5.5, 2.5}, {6.6, 2.45}, {6.7, 3.4}, {5.45, 3.5}};
  for (int i = 0; i < 8; ++i) p.segments.push_back({i, (i + 1) % 8, 1});
  p.segments.push_back({1, 6, 2});  // between the left and middle parts: segment 8
  p.segments.push_back({2, 5, 3});  // between the middle and right parts: segment 9
  for (int i = 0; i < 4; ++i) p.segments.push_back({8 + i, 8 + (i + 1) % 4, 4});
  p.holes = {{6.0, 3.0}};
  p.regions = std::move(regions);
  std::vector<std::string> warnings;
  return validate(p, warnings);
}
Region region(double x, double y, double max_area) { return Region{{x, y}, 0, max_area}; }

// Left 0.05, middle 0.5, right without a bound (a negative one).
std::vector<Region> three_bounds() { return {region(2, 3, 0.05), region(7.5, 1.2, 0.5), region(10, 3, -1)}; }

RefineOptions with_regions(double theta, Method method = Method::Centroid) {
  RefineOptions o;
  o.min_angle_deg = theta;
  o.method = method;
  o.region_area_bounds = true;
  o.trace = true;
  return o;
}

// Both engines: the same mesh, every triangle within its region's bound, certified, theta kept.
void expect_bounded(const Pslg& p, const RefineOptions& o) {
  RefineResult f = fast::refine(p, o), r = reference::refine(p, o);
  ASSERT_EQ(f.cocircular_ties, 0);
  ASSERT_EQ(r.cocircular_ties, 0);
  EXPECT_EQ(f.outcome, Outcome::Converged);
  EXPECT_EQ(difference(f, r), "");
  EXPECT_EQ(impl_test::trace_difference(f.trace, r.trace), "");
  EXPECT_EQ(f.area_refined, r.area_refined);
  EXPECT_GT(f.area_refined, 0);
  for (const RefineResult* run : {&f, &r}) {
    EXPECT_EQ(region_violations(p, run->mesh, o.max_area), std::vector<std::string>{});
    impl_test::InvariantOptions io;
    io.min_angle_deg = o.min_angle_deg;
    EXPECT_EQ(impl_test::check_invariants(p, run->mesh, io), std::vector<std::string>{});
    certify::Options co;
    co.min_angle_deg = o.min_angle_deg;
    EXPECT_TRUE(certify::certify(p, run->mesh, co).certified());
  }
}

TEST(RegionAreas, EveryTriangleWithinItsRegionsBound) {
  const Pslg p = three_parts(three_bounds());
  expect_bounded(p, with_regions(30));
  expect_bounded(p, with_regions(25, Method::Midpoint));
  RefineOptions o = with_regions(30);
  o.order = QueueOrder::Lifo;
  expect_bounded(p, o);
}

// The bounds force refinement: without them the same check fails (the left and
// middle parts keep triangles far above 0.05 and 0.5), so the check can fail.
TEST(RegionAreas, IgnoringTheBoundsFailsTheCheck) {
  const Pslg p = three_parts(three_bounds());
  RefineOptions o = with_regions(30);
  o.region_area_bounds = false;
  for (RefineResult r : {fast::refine(p, o), reference::refine(p, o)}) {
    EXPECT_FALSE(region_violations(p, r.mesh, 0).empty());
    EXPECT_EQ(r.area_refined, 0);
  }
}

// A point split on the segment between two bounded parts keeps each side's region:
// the segments between parts are split, and both sides still meet their own bound.
TEST(RegionAreas, SplitsOfASegmentBetweenRegionsKeepEachSide) {
  const Pslg p = three_parts(three_bounds());
  RefineResult f = fast::refine(p, with_regions(30));
  int between = 0;
  for (const TraceStep& s : f.trace) between += s.split_segment == 8;
  EXPECT_GT(between, 0);
  const std::vector<int> region = regions_of(p, f.mesh);
  int left = 0, middle = 0, right = 0;
  for (int r : region) left += r == 1, middle += r == 2, right += r == 3;
  EXPECT_GT(left, 4 * middle);  // 0.05 against 0.5 on parts of about the same area
  EXPECT_GT(right, 0);
  EXPECT_EQ(left + middle + right, static_cast<int>(region.size()));
}

// With max_area too, the smaller bound applies: 0.2 in the middle (region 0.5)
// and on the right (no region bound), 0.05 on the left.
TEST(RegionAreas, TheSmallerOfMaxAreaAndTheRegionsBoundApplies) {
  const Pslg p = three_parts(three_bounds());
  RefineOptions o = with_regions(30);
  o.max_area = 0.2;
  expect_bounded(p, o);
  RefineResult global_only = fast::refine(p, [&] { RefineOptions g = o; g.region_area_bounds = false; return g; }());
  EXPECT_FALSE(region_violations(p, global_only.mesh, 0.2).empty());  // the left part needs 0.05
}

// Triangle's order: a later region point flooding the same triangles overwrites
// an earlier one, a bound <= 0 included; a region point on a vertex or a segment,
// or in a hole, sets nothing. Each run equals the run without the region lines
// that must have no effect.
TEST(RegionAreas, LaterRegionsOverwriteAndUselessPointsSetNothing) {
  const RefineOptions o = with_regions(30);
  const RefineResult plain = fast::refine(three_parts(three_bounds()), o);
  std::vector<Region> regions = three_bounds();
  regions.insert(regions.begin(), region(1, 1, 0.001));   // left, overwritten by 0.05
  regions.insert(regions.begin(), region(11, 1, 0.002));  // right, overwritten by no bound
  regions.push_back(region(4.1, 0.1, 0.001));             // on a vertex
  regions.push_back(region(6.0, 3.0, 0.001));             // in the hole
  regions.push_back(region(-1.0, 3.0, 0.001));            // outside the domain
  const Pslg p = three_parts(regions);
  for (RefineResult r : {fast::refine(p, o), reference::refine(p, o)}) {
    EXPECT_EQ(difference(plain, r), "");
    EXPECT_EQ(region_violations(p, r.mesh, 0), std::vector<std::string>{});
  }
  // On a segment (x = 1 between two unit squares): the bound applies to neither side.
  Pslg box;
  box.vertices = {{0, 0}, {2, 0}, {2, 1}, {0, 1}, {1, 0}, {1, 1}};
  box.segments = {{0, 4, 1}, {4, 1, 1}, {1, 2, 1}, {2, 5, 1}, {5, 3, 1}, {3, 0, 1}, {4, 5, 2}};
  box.regions = {region(1, 0.5, 0.001)};
  std::vector<std::string> warnings;
  box = validate(box, warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("on a segment"), std::string::npos) << warnings[0];
  RefineOptions b = with_regions(20);
  EXPECT_EQ(fast::refine(box, b).area_refined, 0);
  EXPECT_EQ(reference::refine(box, b).area_refined, 0);
}

// Generated PSLGs (a star polygon, sometimes a crack) with up to four region
// points anywhere in [-1, 1]^2: both engines agree where neither met a
// cocircular tie, and a converged mesh meets every region's bound.
RC_GTEST_PROP(RegionAreas, EnginesAgreeAndMeetTheBoundsOnGeneratedInput, ()) {
  Pslg p = impl_test::to_pslg(*impl_test::gen_raw_pslg(16, 12));
  RC_PRE(!p.vertices.empty());
  // Most region points at the centroid of a triangle of the domain's CDT (inside
  // the domain), some anywhere in [-1, 1]^2; one bound in four is none, the others
  // 1/2 to 1/60 of the domain's area. Uniform draws (rapidcheck's ranges grow with
  // the size, and small sizes would leave every point in a corner, every bound large).
  auto uniform = [](int lo, int hi) { return *rc::gen::resize(100, rc::gen::inRange(lo, hi)); };
  const Mesh cdt = fast::build_cdt(p);
  auto corner = [&](const Tri& t, int i) { return cdt.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>(i)])]; };
  double area = 0;
  for (const Tri& t : cdt.triangles) {
    const Point &a = corner(t, 0), &b = corner(t, 1), &c = corner(t, 2);
    area += ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) / 2;
  }
  const int count = uniform(1, 5);
  for (int k = 0; k < count; ++k) {
    Point at{impl_test::unit(uniform(0, 1 << 20)), impl_test::unit(uniform(0, 1 << 20))};
    if (uniform(0, 4) > 0) {
      const Tri& t = cdt.triangles[static_cast<std::size_t>(uniform(0, static_cast<int>(cdt.triangles.size())))];
      const Point &a = corner(t, 0), &b = corner(t, 1), &c = corner(t, 2);
      at = {(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3};
    }
    p.regions.push_back(region(at.x, at.y, uniform(0, 4) == 0 ? -1.0 : area / uniform(2, 60)));
  }
  RefineOptions o;
  o.min_angle_deg = *rc::gen::inRange(15, 33);
  o.method = *rc::gen::element(Method::Centroid, Method::Midpoint);
  o.region_area_bounds = true;
  if (uniform(0, 4) == 0) o.max_area = area / uniform(2, 30);
  o.max_steiner = 2000;
  RefineResult f = fast::refine(p, o), r = reference::refine(p, o);
  RC_CLASSIFY(f.area_refined > 0, "refined for area");
  RC_CLASSIFY(f.outcome == Outcome::Converged, "converged");
  RC_PRE(f.cocircular_ties == 0 && r.cocircular_ties == 0);
  RC_ASSERT(difference(f, r) == "");
  RC_ASSERT(f.area_refined == r.area_refined);
  if (f.outcome == Outcome::Converged || f.outcome == Outcome::Unimprovable)
    RC_ASSERT(region_violations(p, f.mesh, o.max_area).empty());
}

}  // namespace
}  // namespace lepp
