// SPDX-License-Identifier: GPL-3.0-or-later
// The reference engine on the paper's four problems (Section 5.1): it
// converges for theta = 20, 25, 30 with both methods, and its meshes keep the
// input and meet the angle bound, checked exactly by mesh_checks.
#include <gtest/gtest.h>

#include <string>
#include <tuple>

#include "lepp/io.h"
#include "lepp/reference.h"
#include "lepp/validate.h"
#include "mesh_checks.h"

namespace lepp::reference {
namespace {

using testing::check_ccw;
using testing::check_input_vertices;
using testing::check_locally_delaunay;
using testing::check_min_angle;
using testing::check_segment_chains;

Pslg paper_problem(const std::string& name) {
  std::vector<std::string> warnings;
  return validate(read_poly(std::string(LEPP_SOURCE_DIR) + "/corpus/paper/" + name + ".poly"), warnings);
}

class PaperProblem : public ::testing::TestWithParam<std::tuple<std::string, double, Method>> {};

TEST_P(PaperProblem, ConvergesWithEveryAngleAtLeastTheta) {
  const auto& [name, theta, method] = GetParam();
  Pslg input = paper_problem(name);
  RefineOptions options;
  options.min_angle_deg = theta;
  options.method = method;
  RefineResult result = refine(input, options);
  EXPECT_EQ(result.outcome, Outcome::Converged) << result.stuck;
  EXPECT_TRUE(result.unimprovable.empty());
  EXPECT_GT(result.steiner_points, 0);
  EXPECT_EQ(result.mesh.vertices.size(), input.vertices.size() + static_cast<std::size_t>(result.steiner_points));
  EXPECT_EQ(result.lepp_searches, result.steiner_points);
  EXPECT_GE(result.lepp_triangles, result.lepp_searches);
  EXPECT_EQ(check_min_angle(result.mesh, theta), "");
  EXPECT_EQ(check_input_vertices(result.mesh, input), "");
  EXPECT_EQ(check_segment_chains(result.mesh, input), "");
  EXPECT_EQ(check_ccw(result.mesh), "");
  EXPECT_EQ(check_locally_delaunay(result.mesh), "");
}

INSTANTIATE_TEST_SUITE_P(Reference, PaperProblem,
                         ::testing::Combine(::testing::Values("square400", "circles240", "rect162", "A"),
                                            ::testing::Values(20.0, 25.0, 30.0),
                                            ::testing::Values(Method::Centroid, Method::Midpoint)),
                         [](const auto& info) {
                           return std::get<0>(info.param) + "_" + std::to_string(static_cast<int>(std::get<1>(info.param))) +
                                  "_" + to_string(std::get<2>(info.param));
                         });

// The paper's Table 1 has the centroid method converging up to 36 degrees. Up
// to 35 each run here takes well under a second (fifo order); at 36 the point
// counts depend on the order by orders of magnitude (DESIGN.md, item 7), so
// 36 is measured (lepp paper, the report), not asserted.
INSTANTIATE_TEST_SUITE_P(ReferenceHighAngle, PaperProblem,
                         ::testing::Combine(::testing::Values("square400", "circles240", "rect162", "A"),
                                            ::testing::Values(32.0, 34.0, 35.0), ::testing::Values(Method::Centroid)),
                         [](const auto& info) {
                           return std::get<0>(info.param) + "_" + std::to_string(static_cast<int>(std::get<1>(info.param))) +
                                  "_" + to_string(std::get<2>(info.param));
                         });

// Before refinement: the CDT of the input, Delaunay on unconstrained edges.
TEST(ReferenceCdt, PaperProblemsAreConstrainedDelaunay) {
  for (const char* name : {"square400", "circles240", "rect162", "A"}) {
    Pslg input = paper_problem(name);
    Mesh cdt = build_cdt(input);
    EXPECT_EQ(cdt.vertices.size(), input.vertices.size()) << name;
    EXPECT_EQ(check_locally_delaunay(cdt), "") << name;
    EXPECT_EQ(check_ccw(cdt), "") << name;
    EXPECT_EQ(check_input_vertices(cdt, input), "") << name;
    EXPECT_EQ(check_segment_chains(cdt, input), "") << name;
  }
}

// Same input, same options: the same mesh, bit for bit.
TEST(ReferenceRefine, IsDeterministic) {
  Pslg input = paper_problem("A");
  RefineOptions options;
  options.trace = true;
  RefineResult a = refine(input, options), b = refine(input, options);
  EXPECT_EQ(a.mesh.vertices, b.mesh.vertices);
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
  ASSERT_EQ(a.trace.size(), b.trace.size());
  ASSERT_EQ(a.trace.size(), static_cast<std::size_t>(a.steiner_points));
  for (std::size_t i = 0; i < a.trace.size(); ++i) {
    EXPECT_EQ(a.trace[i].point, b.trace[i].point);
    // The trace's points are the Steiner vertices, in insertion order.
    EXPECT_EQ(a.trace[i].point, a.mesh.vertices[input.vertices.size() + i]);
  }
}

}  // namespace
}  // namespace lepp::reference

namespace lepp::reference {
namespace {

// The lifo discipline is an option, not the default: it converges on the
// paper's problems at 30 degrees too, through a different sequence of insertions.
TEST(QueueOrder, LifoConvergesThroughAnotherSequence) {
  for (const char* name : {"square400", "circles240", "rect162", "A"}) {
    Pslg input = paper_problem(name);
    RefineOptions fifo, lifo;
    fifo.trace = lifo.trace = true;
    lifo.order = QueueOrder::Lifo;
    RefineResult a = refine(input, fifo), b = refine(input, lifo);
    EXPECT_EQ(b.outcome, Outcome::Converged) << name;
    EXPECT_EQ(testing::check_min_angle(b.mesh, 30), "") << name;
    EXPECT_EQ(testing::check_locally_delaunay(b.mesh), "") << name;
    bool same = a.trace.size() == b.trace.size();
    for (std::size_t i = 0; same && i < a.trace.size(); ++i) same = a.trace[i].point == b.trace[i].point;
    EXPECT_FALSE(same) << name;
  }
}

// Four cocircular points: the initial CDT's diagonal is a tie, counted once;
// right isosceles triangles need no refinement at 30 degrees.
TEST(CocircularTies, UnitSquareDiagonalIsOneTie) {
  Pslg square;
  square.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  square.segments = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}, {3, 0, 0}};
  RefineResult r = refine(square, RefineOptions{});
  EXPECT_EQ(r.steiner_points, 0);
  EXPECT_EQ(r.cocircular_ties, 1);
  EXPECT_EQ(refine(paper_problem("circles240"), RefineOptions{}).cocircular_ties, 0);
}

}  // namespace
}  // namespace lepp::reference
