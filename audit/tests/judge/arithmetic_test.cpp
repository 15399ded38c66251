// SPDX-License-Identifier: GPL-3.0-or-later
// What the numbers a program wrote say about its arithmetic (lepp/audit/judge/arithmetic.h):
// each rule names what it must and nothing on a program that wrote the exact doubles.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "lepp/audit/judge/arithmetic.h"

namespace {

using lepp::Point;
using lepp::audit::ConformanceCandidate;
using lepp::audit::ConformanceFailure;

// Through a volatile, as in arithmetic.cpp: GCC 12 drops a vectorized float round trip.
double to_float(double x) {
  volatile float f = static_cast<float>(x);
  return f;
}
double six_digits(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%g", x);
  return std::strtod(buf, nullptr);
}

// A square with corners no float holds, and a mesh of it with one Steiner point.
lepp::Pslg square() {
  lepp::Pslg p;
  p.vertices = {{0.1, 0.1}, {1.3, 0.1}, {1.3, 1.7}, {0.1, 1.7}};
  p.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  return p;
}
// The mesh as a program writes it, each coordinate through `written`.
template <class Written>
lepp::Mesh mesh_through(Written written) {
  lepp::Mesh m;
  const lepp::Pslg input = square();
  for (const Point& v : input.vertices) m.vertices.push_back(Point{written(v.x), written(v.y)});
  m.vertices.push_back(Point{written(0.7), written(0.9)});
  m.triangles = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  return m;
}
double exact(double x) { return x; }

TEST(Arithmetic, MeshAtFloatsIsSinglePrecision) {
  const auto e = lepp::audit::mesh_arithmetic(square(), mesh_through(to_float));
  EXPECT_EQ(e.name, "single-precision") << e.what;
  EXPECT_EQ(e.moved, 4u);
  EXPECT_EQ(e.rounded, 4u);
}

// The input vertices at their floats, the Steiner point a double no float holds: the
// program read its input as float and computed in double. One coordinate of the
// added point a double is enough to tell it from single-precision.
TEST(Arithmetic, InputAtFloatsPointsInDoubleIsFloatInput) {
  lepp::Mesh m = mesh_through(to_float);
  m.vertices[4] = {0.7, to_float(0.9)};
  const auto e = lepp::audit::mesh_arithmetic(square(), m);
  EXPECT_EQ(e.name, "float-input") << e.what;
  EXPECT_EQ(e.moved, 4u);
  EXPECT_NE(e.what.find("the input vertices are floats, not the points it added"), std::string::npos) << e.what;
  EXPECT_NE(std::string(lepp::audit::arithmetic_definition("float-input")), "");
  // One input vertex kept where it is: nothing shows.
  m.vertices[2] = square().vertices[2];
  EXPECT_EQ(lepp::audit::mesh_arithmetic(square(), m).name, "");
}

TEST(Arithmetic, MeshWithSixDigitsIsPrintedDigits) {
  // 0.1 has one digit: the Steiner point's needs more than 6 for the rule to see digits at all.
  lepp::Pslg p = square();
  p.vertices[1] = {1.0 / 3, 0.1};
  lepp::Mesh m = mesh_through(six_digits);
  m.vertices[1] = {six_digits(1.0 / 3), six_digits(0.1)};
  const auto e = lepp::audit::mesh_arithmetic(p, m);
  EXPECT_EQ(e.name, "printed-digits") << e.what;
  EXPECT_EQ(e.digits, 6);
  EXPECT_EQ(e.moved, 1u);
}

TEST(Arithmetic, ExactMeshNamesNothing) {
  EXPECT_EQ(lepp::audit::mesh_arithmetic(square(), mesh_through(exact)).name, "");
  // One input vertex kept where it is: not a program that rounds every coordinate.
  lepp::Mesh m = mesh_through(to_float);
  m.vertices[2] = square().vertices[2];
  EXPECT_EQ(lepp::audit::mesh_arithmetic(square(), m).name, "");
  // Every vertex a float, but an input of floats: rounding moves nothing, nothing shows.
  lepp::Pslg floats = square();
  for (Point& v : floats.vertices) v = {to_float(v.x), to_float(v.y)};
  EXPECT_EQ(lepp::audit::mesh_arithmetic(floats, mesh_through(to_float)).name, "");
}

// A failing step whose nearest paper choice is (1/3, 2/3) with the replay's tolerance (8 ulps of 1).
ConformanceFailure step_at(Point p) {
  ConformanceFailure f;
  f.point = p;
  ConformanceCandidate c;
  c.point = {1.0 / 3, 2.0 / 3};
  c.tolerance = 8 * 2.220446049250313e-16;
  c.distance = std::max(std::abs(p.x - c.point.x), std::abs(p.y - c.point.y));
  f.candidates.push_back(c);
  return f;
}

TEST(Arithmetic, StepAtTheChoicesFloatIsSinglePrecision) {
  EXPECT_EQ(lepp::audit::step_arithmetic(step_at({to_float(1.0 / 3), to_float(2.0 / 3)})).name, "single-precision");
}

TEST(Arithmetic, StepAtTheChoicesSixDigitsIsPrintedDigits) {
  const auto e = lepp::audit::step_arithmetic(step_at({six_digits(1.0 / 3), six_digits(2.0 / 3)}));
  EXPECT_EQ(e.name, "printed-digits") << e.what;
  EXPECT_EQ(e.digits, 6);
}

TEST(Arithmetic, StepElsewhereNamesNothing) {
  // The choice itself, a float far from it, a short point far from it, no choice at all.
  EXPECT_EQ(lepp::audit::step_arithmetic(step_at({1.0 / 3, 2.0 / 3})).name, "");
  EXPECT_EQ(lepp::audit::step_arithmetic(step_at({0.25, 0.75})).name, "");
  // Four digits, but more than half a unit of the fourth from the choice: not its rounding.
  EXPECT_EQ(lepp::audit::step_arithmetic(step_at({0.3334, 0.6667})).name, "");
  EXPECT_EQ(lepp::audit::step_arithmetic(ConformanceFailure{}).name, "");
  // A float one float-tolerance too far (64 float ulps of 1 away).
  EXPECT_EQ(lepp::audit::step_arithmetic(step_at({to_float(1.0 / 3) + 64 * 1.1920929e-7, to_float(2.0 / 3)})).name, "");
}

}  // namespace
