// SPDX-License-Identifier: GPL-3.0-or-later
// Every run ends (ALGORITHM.md Sections 8 and 9): the Steiner budget, the edge
// floor and the time limit stop a run with their outcome and name the triangle
// being processed; small input angles give outcome unimprovable with the
// triangles listed; a size bound makes every triangle small. A time limit
// that does not expire changes nothing, and progress is reported every 1000 points.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "lepp/io.h"
#include "lepp/reference.h"
#include "lepp/validate.h"
#include "mesh_checks.h"

namespace lepp::reference {
namespace {

Pslg square400() {
  std::vector<std::string> warnings;
  return validate(read_poly(std::string(LEPP_SOURCE_DIR) + "/corpus/paper/square400.poly"), warnings);
}

// A closed triangle with a 5 degree angle at vertex 0 between segments 0 and 2.
Pslg wedge(double degrees) {
  Pslg p;
  double r = degrees * M_PI / 180;
  p.vertices = {{0, 0}, {10, 0}, {10 * std::cos(r), 10 * std::sin(r)}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 0, 0}};
  return p;
}

TEST(Guards, SteinerBudgetStopsWithAValidMesh) {
  Pslg input = square400();
  RefineOptions options;
  options.max_steiner = 7;
  RefineResult result = refine(input, options);
  EXPECT_EQ(result.outcome, Outcome::SteinerBudget);
  EXPECT_EQ(result.steiner_points, 7);
  EXPECT_NE(result.stuck.find("triangle ("), std::string::npos) << result.stuck;
  EXPECT_NE(result.stuck.find("Lepp"), std::string::npos) << result.stuck;
  EXPECT_EQ(testing::check_locally_delaunay(result.mesh), "");
  EXPECT_EQ(testing::check_segment_chains(result.mesh, input), "");
  EXPECT_NE(testing::check_min_angle(result.mesh, 30), "");  // stopped early: still bad triangles
  EXPECT_EQ(exit_status(result.outcome), 3);
}

TEST(Guards, EdgeFloorStops) {
  Pslg input = square400();
  RefineOptions options;
  // The shortest input segment: the first edge shorter than it stops the run.
  options.edge_floor = std::ldexp(default_edge_floor(input), 20);
  RefineResult result = refine(input, options);
  EXPECT_EQ(result.outcome, Outcome::EdgeFloor);
  EXPECT_FALSE(result.stuck.empty());
  EXPECT_GT(result.steiner_points, 0);
}

TEST(Guards, TimeLimitStops) {
  RefineOptions options;
  options.time_limit_seconds = 1e-9;
  RefineResult result = refine(square400(), options);
  EXPECT_EQ(result.outcome, Outcome::TimeLimit);
  EXPECT_EQ(result.steiner_points, 0);
  EXPECT_FALSE(result.stuck.empty());
}

// A limit that does not expire changes nothing; the progress callback hears
// every thousandth Steiner point, in order.
TEST(Guards, ProgressEveryThousandPointsAndALimitThatDoesNotExpire) {
  RefineOptions options;
  options.max_area = 1;  // [0,100]^2: thousands of Steiner points
  RefineResult plain = refine(square400(), options);
  ASSERT_EQ(plain.outcome, Outcome::Converged);
  ASSERT_GE(plain.steiner_points, 2000) << "the test needs a longer run";
  std::vector<std::int64_t> heard;
  options.on_progress = [&heard](std::int64_t n) { heard.push_back(n); };
  options.time_limit_seconds = 1e9;
  RefineResult watched = refine(square400(), options);
  EXPECT_EQ(watched.outcome, Outcome::Converged);
  EXPECT_EQ(watched.steiner_points, plain.steiner_points);
  EXPECT_TRUE(watched.mesh.triangles == plain.mesh.triangles);
  ASSERT_EQ(heard.size(), std::size_t(plain.steiner_points / 1000));
  for (std::size_t i = 0; i < heard.size(); ++i) EXPECT_EQ(heard[i], std::int64_t(1000 * (i + 1)));
}

TEST(Guards, SmallInputAngleIsUnimprovable) {
  Pslg input = wedge(5);
  RefineOptions options;
  options.min_angle_deg = 30;
  RefineResult result = refine(input, options);
  EXPECT_EQ(result.outcome, Outcome::Unimprovable) << result.stuck;
  ASSERT_FALSE(result.unimprovable.empty());
  std::vector<Tri> listed;
  for (const UnimprovableTriangle& u : result.unimprovable) {
    EXPECT_EQ(u.apex, 0);
    EXPECT_EQ(u.segment1, 0);
    EXPECT_EQ(u.segment2, 2);
    EXPECT_NEAR(u.input_angle_deg, 5, 1e-9);
    listed.push_back(u.triangle);
  }
  // Only the listed triangles are below 30 degrees, and they are listed in key order.
  EXPECT_EQ(testing::check_min_angle(result.mesh, 30, listed), "");
  EXPECT_NE(testing::check_min_angle(result.mesh, 30), "");
  for (std::size_t i = 1; i < listed.size(); ++i) {
    Tri a = listed[i - 1], b = listed[i];
    std::sort(a.begin(), a.end()), std::sort(b.begin(), b.end());
    EXPECT_LT(a, b);
  }
  EXPECT_EQ(exit_status(result.outcome), 3);
}

TEST(Guards, AngleAboveThetaIsNotUnimprovable) {
  RefineOptions options;
  options.min_angle_deg = 30;
  RefineResult result = refine(wedge(40), options);
  EXPECT_EQ(result.outcome, Outcome::Converged);
  EXPECT_TRUE(result.unimprovable.empty());
}

TEST(SizeBound, MaxAreaMakesEveryTriangleSmall) {
  Pslg input = square400();
  RefineOptions options;
  options.min_angle_deg = 20;
  options.max_area = 5;  // the square is [0,100]^2
  RefineResult result = refine(input, options);
  EXPECT_EQ(result.outcome, Outcome::Converged) << result.stuck;
  EXPECT_EQ(testing::check_max_area(result.mesh, options.max_area), "");
  EXPECT_EQ(testing::check_min_angle(result.mesh, 20), "");
  EXPECT_NE(testing::check_max_area(refine(input, RefineOptions{}).mesh, options.max_area), "");
}

TEST(Callbacks, OnInsertionSeesEveryIntermediateMesh) {
  std::vector<std::string> warnings;
  Pslg input = validate(read_poly(std::string(LEPP_SOURCE_DIR) + "/corpus/paper/A.poly"), warnings);
  RefineOptions options;
  std::int64_t calls = 0;
  options.on_insertion = [&](const Mesh& mesh) {
    ++calls;
    EXPECT_EQ(mesh.vertices.size(), input.vertices.size() + static_cast<std::size_t>(calls));
    EXPECT_EQ(testing::check_locally_delaunay(mesh), "");
    EXPECT_EQ(testing::check_segment_chains(mesh, input), "");
  };
  RefineResult result = refine(input, options);
  EXPECT_EQ(calls, result.steiner_points);
}

}  // namespace
}  // namespace lepp::reference
