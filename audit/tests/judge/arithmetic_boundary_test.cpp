// SPDX-License-Identifier: GPL-3.0-or-later
// The arithmetic names at the ends of their rules (issue 42; lepp/audit/judge/arithmetic.h):
// printed-digits for a program that writes 15 and 16 significant digits and not for
// one that writes 17 (a double in full), on the final mesh and on a step; the step's
// bound of half a unit of the D-th digit on both sides; single-precision's float
// tolerance at exactly its value and one float further. Each test names the mutants
// of tools/mutation/mutants.txt it kills.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "lepp/audit/judge/arithmetic.h"

namespace {

using lepp::Point;
using lepp::audit::ConformanceCandidate;
using lepp::audit::ConformanceFailure;

// x written with d significant digits and read back, as a program's stream does.
double written(double x, int d) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", d, x);
  return std::strtod(buf, nullptr);
}

// A square whose corner (0.1 + 0.2, 0.1) needs 17 digits (0.30000000000000004): 15 and
// 16 digits both move it, to 0.3. The mesh adds one Steiner point at (1/3, 2/3),
// whose coordinates need 16 digits: written with D digits, the mesh's coordinates need D.
lepp::Pslg square() {
  lepp::Pslg p;
  p.vertices = {{0.1 + 0.2, 0.1}, {1.5, 0.1}, {1.5, 1.25}, {0.1 + 0.2, 1.25}};
  p.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  return p;
}
lepp::Mesh mesh_with_digits(int d) {
  lepp::Mesh m;
  for (const Point& v : square().vertices) m.vertices.push_back(Point{written(v.x, d), written(v.y, d)});
  m.vertices.push_back(Point{written(1.0 / 3, d), written(2.0 / 3, d)});
  m.triangles = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  return m;
}

// The premises: what each number needs.
TEST(ArithmeticBoundary, ThePremises) {
  ASSERT_NE(written(0.1 + 0.2, 16), 0.1 + 0.2);  // needs 17
  ASSERT_EQ(written(1.0 / 3, 16), 1.0 / 3);      // needs 16
  ASSERT_NE(written(1.0 / 3, 15), 1.0 / 3);
  ASSERT_EQ(written(2.0 / 3, 16), 2.0 / 3);
}

// Kills audit-printed-digits-below-15 (D < 15 asked) and audit-printed-digits-15-most
// (the rule ends at 15 digits: a stream at setprecision(16) named nothing before issue 42).
TEST(ArithmeticBoundary, MeshWrittenWithFifteenAndSixteenDigitsIsPrintedDigits) {
  for (int d : {15, 16}) {
    const auto e = lepp::audit::mesh_arithmetic(square(), mesh_with_digits(d));
    EXPECT_EQ(e.name, "printed-digits") << d << " digits: " << e.what;
    EXPECT_EQ(e.digits, d) << e.what;
    EXPECT_EQ(e.moved, 2u) << e.what;  // the two corners at 0.30000000000000004
  }
  // 6 digits, a stream's default, as before.
  EXPECT_EQ(lepp::audit::mesh_arithmetic(square(), mesh_with_digits(6)).name, "printed-digits");
}

// Kills audit-printed-digits-17-is-printed (the rule taken up to 17 digits: a program
// writing doubles in full is named).
TEST(ArithmeticBoundary, MeshWrittenWithSeventeenDigitsNamesNothing) {
  const auto e = lepp::audit::mesh_arithmetic(square(), mesh_with_digits(17));
  EXPECT_EQ(e.name, "") << e.what;
  // One corner written in full among 16-digit ones: then some coordinate needs 17 digits.
  lepp::Mesh m = mesh_with_digits(16);
  m.vertices[3] = square().vertices[3];
  EXPECT_EQ(lepp::audit::mesh_arithmetic(square(), m).name, "");
}

// A failing step whose nearest paper choice is `choice`, with the replay's tolerance (8 ulps of 1).
ConformanceFailure step(Point p, Point choice) {
  ConformanceFailure f;
  f.point = p;
  ConformanceCandidate c;
  c.point = choice;
  c.tolerance = 8 * DBL_EPSILON;
  c.distance = std::max(std::abs(p.x - choice.x), std::abs(p.y - choice.y));
  f.candidates.push_back(c);
  return f;
}

TEST(ArithmeticBoundary, StepWrittenWithFifteenAndSixteenDigitsIsPrintedDigits) {
  const Point choice{0.1 + 0.2, 2.0 / 3};  // x needs 17 digits
  for (int d : {15, 16}) {
    const auto e = lepp::audit::step_arithmetic(step({written(choice.x, d), written(choice.y, d)}, choice));
    EXPECT_EQ(e.name, "printed-digits") << d << " digits: " << e.what;
    EXPECT_EQ(e.digits, d) << e.what;
  }
  // Written in full: the choice itself, nothing to name.
  EXPECT_EQ(lepp::audit::step_arithmetic(step(choice, choice)).name, "");
}

// 0.30000000000000004 written with 16 digits reads back as 0.3, 5.55e-17 away: more
// than half a unit of the 16th digit (5e-17), because the decimal 0.3 itself reads
// back half an ulp off. The bound before issue 42 (half a unit, and a millionth)
// missed that read-back: kills audit-printed-digits-no-read-back (the tolerance
// dropped from the bound).
TEST(ArithmeticBoundary, StepBoundCountsTheReadBack) {
  const Point choice{0.1 + 0.2, 2.0 / 3};
  ASSERT_GT(std::abs(0.3 - choice.x), 5e-17 * (1 + 1e-6));
  EXPECT_EQ(lepp::audit::step_arithmetic(step({0.3, 2.0 / 3}, choice)).name, "printed-digits");
}

// Half a unit of the D-th digit on each side: 1/3 and 2/3 at 5 digits are
// 0.33333 and 0.66667; one unit of the 5th digit off is not their rounding.
// Kills audit-printed-digits-whole-unit (a whole unit of the digit accepted).
TEST(ArithmeticBoundary, StepHalfAUnitOfTheLastDigitOnBothSides) {
  const Point choice{1.0 / 3, 2.0 / 3};
  EXPECT_EQ(lepp::audit::step_arithmetic(step({0.33333, 0.66667}, choice)).name, "printed-digits");
  EXPECT_EQ(lepp::audit::step_arithmetic(step({0.33334, 0.66667}, choice)).name, "");
  EXPECT_EQ(lepp::audit::step_arithmetic(step({0.33333, 0.66668}, choice)).name, "");
  EXPECT_EQ(lepp::audit::step_arithmetic(step({0.33332, 0.66666}, choice)).name, "");
}

// single-precision's bound: the point tolerance in float units, 8 FLT_EPSILON = 2^-20
// at scale 1. The choice's x is a float 2^-20 from the point's, its y no float: the
// distance is exactly the bound (named), and one float further it is not.
// Kills audit-single-precision-open-bound (< for <=) and
// audit-single-precision-double-units (the tolerance left in DBL_EPSILON units).
TEST(ArithmeticBoundary, SinglePrecisionAtExactlyTheFloatTolerance) {
  const float y = static_cast<float>(2.0 / 3);
  const Point choice{0.25 + std::ldexp(1.0, -20), 2.0 / 3};
  ASSERT_EQ(static_cast<double>(static_cast<float>(choice.x)), choice.x);  // the choice's x is a float
  ASSERT_NE(static_cast<double>(y), choice.y);                           // its y is not
  const auto at = lepp::audit::step_arithmetic(step({0.25, y}, choice));
  EXPECT_EQ(at.name, "single-precision") << at.what;
  const float beyond = std::nextafter(0.25f, 0.0f);
  EXPECT_EQ(lepp::audit::step_arithmetic(step({beyond, y}, choice)).name, "");
  // Well inside: 2^-22 away.
  EXPECT_EQ(lepp::audit::step_arithmetic(step({0.25 + 3 * std::ldexp(1.0, -22), y}, choice)).name, "single-precision");
}

}  // namespace
