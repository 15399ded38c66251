// SPDX-License-Identifier: GPL-3.0-or-later
// validate() on PSLGs built in code: each repair does what validate.h says,
// each error names what is wrong, and exact predicates decide.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "lepp/io.h"
#include "lepp/validate.h"

namespace lepp {
namespace {

Pslg square(double side = 1) {
  Pslg p;
  p.source = "square";
  p.vertices = {{0, 0}, {side, 0}, {side, side}, {0, side}};
  p.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  return p;
}

bool mentions(const std::vector<std::string>& warnings, const std::string& text) {
  return std::any_of(warnings.begin(), warnings.end(), [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

std::string error_of(const Pslg& p) {
  std::vector<std::string> warnings;
  try {
    validate(p, warnings);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Validate, CleanSquareUnchanged) {
  std::vector<std::string> warnings;
  Pslg v = validate(square(), warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(v.vertices.size(), 4u);
  ASSERT_EQ(v.segments.size(), 4u);
  for (int s = 0; s < 4; ++s) EXPECT_EQ(v.segments[s].a, s);
}

TEST(Validate, DuplicateVerticesMergeWithWarning) {
  Pslg p = square();
  p.vertices.push_back({1, 0});  // vertex 5 duplicates vertex 2
  p.segments[1].a = 4;
  std::vector<std::string> warnings;
  Pslg v = validate(p, warnings);
  EXPECT_EQ(v.vertices.size(), 4u);
  EXPECT_EQ(v.segments[1].a, 1);
  EXPECT_TRUE(mentions(warnings, "vertex 5 duplicates vertex 2")) << warnings.size();
}

// Dropped with a warning, as Triangle does (issue 20): both endpoints one vertex, or
// one point once duplicates merge.
TEST(Validate, ZeroLengthSegmentDroppedWithWarning) {
  Pslg p = square();
  p.vertices.push_back({1, 1});
  p.segments.push_back({2, 4});  // same point as vertex 3 once merged
  p.segments.push_back({1, 1});  // one vertex twice
  std::vector<std::string> warnings;
  Pslg v = validate(p, warnings);
  EXPECT_EQ(v.segments.size(), 4u);
  EXPECT_TRUE(mentions(warnings, "segment 5 has zero length (vertices 3 and 5 are the same point); dropped"));
  EXPECT_TRUE(mentions(warnings, "segment 6 has zero length (both endpoints are vertex 2); dropped"));
  EXPECT_EQ(v.segment_origin, (std::vector<int>{0, 1, 2, 3}));
}

TEST(Validate, RepeatedSegmentDroppedWithWarning) {
  Pslg p = square();
  p.segments.push_back({1, 0});  // segment 1 reversed
  std::vector<std::string> warnings;
  Pslg v = validate(p, warnings);
  EXPECT_EQ(v.segments.size(), 4u);
  EXPECT_TRUE(mentions(warnings, "segment 5 repeats segment 1"));
}

TEST(Validate, VertexInsideSegmentSplitsIt) {
  Pslg p = square(2);
  p.vertices.push_back({1, 0});  // on segment 1, strictly inside
  std::vector<std::string> warnings;
  Pslg v = validate(p, warnings);
  ASSERT_EQ(v.segments.size(), 5u);
  EXPECT_EQ(v.segments[0].a, 0);
  EXPECT_EQ(v.segments[0].b, 4);
  EXPECT_EQ(v.segments[1].a, 4);
  EXPECT_EQ(v.segments[1].b, 1);
  EXPECT_TRUE(mentions(warnings, "segment 1 passes through vertex 5; split there"));
}

TEST(Validate, TJunctionIsASplitNotACrossing) {
  Pslg p = square(2);
  p.vertices.push_back({1, 0});
  p.vertices.push_back({1, 1});
  p.segments.push_back({5, 4});  // ends on segment 1
  std::vector<std::string> warnings;
  Pslg v = validate(p, warnings);
  EXPECT_EQ(v.segments.size(), 6u);
}

TEST(Validate, OverlappingCollinearSegmentsSplitAndDedupe) {
  Pslg p = square(3);
  p.vertices.push_back({1, 0});
  p.vertices.push_back({2, 0});
  p.segments.push_back({0, 5});  // (0,0)-(2,0) overlaps segment 1 on [0,2]
  p.segments.push_back({4, 1});  // (1,0)-(3,0) overlaps both
  std::vector<std::string> warnings;
  Pslg v = validate(p, warnings);
  // Bottom side: three pieces 0-4, 4-5, 5-1, each once; plus three other sides.
  EXPECT_EQ(v.segments.size(), 6u);
  EXPECT_TRUE(mentions(warnings, "segment 5 lies along earlier segments"));
  EXPECT_TRUE(mentions(warnings, "segment 6 lies along earlier segments"));
}

TEST(Validate, PartialOverlapKeepsTheRest) {
  Pslg p;
  p.source = "overlap";
  p.vertices = {{0, 0}, {2, 0}, {1, 0}, {3, 0}, {1, 2}};
  p.segments = {{0, 1}, {2, 3}, {3, 4}, {4, 0}};  // [0,2] and [1,3] overlap on [1,2]
  std::vector<std::string> warnings;
  Pslg v = validate(p, warnings);
  EXPECT_EQ(v.segments.size(), 5u);  // 0-2, 2-1, 1-3, 3-4, 4-0
  EXPECT_TRUE(mentions(warnings, "segment 2 overlaps segment 1"));
}

TEST(Validate, CrossingNamesBothSegments) {
  Pslg p = square();
  p.segments.push_back({0, 2});
  p.segments.push_back({1, 3});
  p.segment_lines = {10, 11, 12, 13, 14, 15};
  const std::string what = error_of(p);
  EXPECT_NE(what.find("square:15: segments 6 and 5 (line 14) cross"), std::string::npos) << what;
}

TEST(Validate, NearMissIsNotACrossing) {
  // Segment 6 stops one ulp short of the diagonal (segment 5): exact
  // predicates see no crossing; one ulp further, they see one.
  Pslg p = square(2);
  p.vertices.push_back({std::nextafter(1.0, 0.0), 1});
  p.vertices.push_back({0.5, 1.5});
  p.segments.push_back({0, 2});
  p.segments.push_back({5, 4});
  std::vector<std::string> warnings;
  EXPECT_NO_THROW(validate(p, warnings)) << error_of(p);
  p.vertices[4].x = std::nextafter(1.0, 2.0);
  EXPECT_NE(error_of(p).find("segments 6 and 5 cross"), std::string::npos) << error_of(p);
}

TEST(Validate, CollinearInputIsAnErrorDecidedExactly) {
  Pslg p;
  p.source = "line";
  p.vertices = {{0, 0}, {1e20, 1e20}, {3, 3}, {-7, -7}};
  EXPECT_NE(error_of(p).find("fewer than three non-collinear vertices"), std::string::npos);
  // One ulp off the line: a real triangle (and a domain once closed).
  p.vertices[2].y = std::nextafter(3.0, 4.0);
  p.segments = {{0, 2}, {2, 1}, {1, 0}};
  std::vector<std::string> warnings;
  EXPECT_NO_THROW(validate(p, warnings)) << error_of(p);
}

TEST(Validate, NonFiniteAndOutOfRangeFromGeneratedPslgs) {
  Pslg p = square();
  p.vertices[1].x = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(error_of(p).find("not finite"), std::string::npos);
  p = square();
  p.segments[0].b = 9;
  EXPECT_NE(error_of(p).find("out of range"), std::string::npos);
}

TEST(Validate, HolePointsThatRemoveNothingWarn) {
  Pslg p = square(2);
  p.holes = {{5, 5}, {1, 0}, {0, 0}};  // outside, on a segment, on a vertex
  std::vector<std::string> warnings;
  validate(p, warnings);
  EXPECT_TRUE(mentions(warnings, "hole point 1 lies outside the domain"));
  EXPECT_TRUE(mentions(warnings, "hole point 2 lies on a segment"));
  EXPECT_TRUE(mentions(warnings, "hole point 3 lies on vertex 1"));
}

// A region point whose area bound reaches no triangle warns; one without a
// bound (attribute only) or inside the domain does not; a NaN is an error.
TEST(Validate, RegionPointsWhoseBoundAppliesToNothingWarn) {
  Pslg p = square(4);
  p.vertices.insert(p.vertices.end(), {{1, 1}, {2, 1}, {1, 2}});
  p.segments.insert(p.segments.end(), {{4, 5}, {5, 6}, {6, 4}});
  p.holes = {{1.2, 1.2}};
  p.regions = {Region{{5, 5}, 0, 1},  Region{{2, 0}, 0, 1},  Region{{0, 0}, 0, 1},  Region{{1.3, 1.2}, 0, 1},
               Region{{5, 5}, 0, -1}, Region{{3, 3}, 0, 1}};
  std::vector<std::string> warnings;
  validate(p, warnings);
  EXPECT_TRUE(mentions(warnings, "region point 1 lies outside the domain"));
  EXPECT_TRUE(mentions(warnings, "region point 2 lies on a segment"));
  EXPECT_TRUE(mentions(warnings, "region point 3 lies on a vertex"));
  EXPECT_TRUE(mentions(warnings, "region point 4 lies in a hole"));
  EXPECT_FALSE(mentions(warnings, "region point 5"));
  EXPECT_FALSE(mentions(warnings, "region point 6"));
  p.regions = {Region{{3, 3}, 0, std::nan("")}};
  EXPECT_NE(error_of(p).find("region 1"), std::string::npos);
  p.regions = {Region{{std::numeric_limits<double>::infinity(), 3}, 0, 1}};
  EXPECT_NE(error_of(p).find("not finite"), std::string::npos);
}

TEST(Validate, HoleInsideAnInnerRegionIsQuiet) {
  Pslg p = square(4);
  p.vertices.insert(p.vertices.end(), {{1, 1}, {2, 1}, {1, 2}});
  p.segments.insert(p.segments.end(), {{4, 5}, {5, 6}, {6, 4}});
  p.holes = {{1.2, 1.2}};
  std::vector<std::string> warnings;
  validate(p, warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
}

TEST(Validate, EmptyDomainIsAnError) {
  Pslg p = square();
  p.segments.pop_back();  // an open polyline encloses nothing
  EXPECT_NE(error_of(p).find("domain is empty"), std::string::npos);
  p = square();
  p.holes = {{0.5, 0.5}};
  EXPECT_NE(error_of(p).find("domain is empty"), std::string::npos);
}

TEST(Validate, WarningsAreCappedPerKind) {
  Pslg p = square();
  for (int i = 0; i < 1000; ++i) p.vertices.push_back({0.5, 0});  // one real vertex, 999 duplicates
  std::vector<std::string> warnings;
  Pslg v = validate(p, warnings);
  EXPECT_EQ(v.vertices.size(), 5u);
  EXPECT_LT(warnings.size(), 30u);
  EXPECT_TRUE(mentions(warnings, "more warnings of this kind (duplicate vertex)"));
}

}  // namespace
}  // namespace lepp
