// SPDX-License-Identifier: GPL-3.0-or-later
// The filtered predicates agree with exact arithmetic (CGAL Epick predicates,
// CGAL::Exact_rational) on near-degenerate, tiny and huge inputs, where the
// double filter must hand over to the exact path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>

#include "predicates.h"

namespace lepp::fast {
namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Q = CGAL::Exact_rational;
K::Point_2 kp(const Point& p) { return {p.x, p.y}; }

int exact_compare_sqlen(const Point& a, const Point& b, const Point& c, const Point& d) {
  Q l1 = (Q(b.x) - Q(a.x)) * (Q(b.x) - Q(a.x)) + (Q(b.y) - Q(a.y)) * (Q(b.y) - Q(a.y));
  Q l2 = (Q(d.x) - Q(c.x)) * (Q(d.x) - Q(c.x)) + (Q(d.y) - Q(c.y)) * (Q(d.y) - Q(c.y));
  return l1 < l2 ? -1 : l1 > l2 ? 1 : 0;
}
bool exact_skinny_at(const Point& o, const Point& p, const Point& q, double s) {
  Q ux = Q(p.x) - Q(o.x), uy = Q(p.y) - Q(o.y), wx = Q(q.x) - Q(o.x), wy = Q(q.y) - Q(o.y);
  Q cross = ux * wy - uy * wx;
  return cross * cross < Q(s) * (ux * ux + uy * uy) * (wx * wx + wy * wy);
}
bool exact_area_above(const Point& a, const Point& b, const Point& c, double twice) {
  Q cross = (Q(b.x) - Q(a.x)) * (Q(c.y) - Q(a.y)) - (Q(b.y) - Q(a.y)) * (Q(c.x) - Q(a.x));
  if (cross < 0) cross = -cross;
  return cross > Q(twice);
}

// Nudges x by k ulps.
double nudge(double x, int k) {
  for (; k > 0; --k) x = std::nextafter(x, HUGE_VAL);
  for (; k < 0; ++k) x = std::nextafter(x, -HUGE_VAL);
  return x;
}

struct Scale {
  double factor, shift;
};

class NearDegenerate : public ::testing::TestWithParam<Scale> {};

TEST_P(NearDegenerate, AgreeWithExactArithmetic) {
  const Scale sc = GetParam();
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> k(-3, 3);
  auto pt = [&](double x, double y) { return Point{x * sc.factor + sc.shift, y * sc.factor + sc.shift}; };
  int undecided_by_filter_would_be_wrong = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    Point a = pt(u(rng), u(rng)), b = pt(u(rng), u(rng));
    double t = u(rng);
    // c near the line ab, d near the circle through a, b, c or a mirror of it.
    Point c{nudge(a.x + t * (b.x - a.x), k(rng)), nudge(a.y + t * (b.y - a.y), k(rng))};
    Point d{nudge(a.x + b.x - c.x, k(rng)), nudge(a.y + b.y - c.y, k(rng))};
    ASSERT_EQ(orient(a, b, c), static_cast<int>(CGAL::orientation(kp(a), kp(b), kp(c))));
    Point e = pt(u(rng), u(rng));
    if (CGAL::orientation(kp(a), kp(b), kp(e)) == CGAL::LEFT_TURN) {
      // Points of the parallelogram a, e, b, a+b-e: cocircular only for a rectangle; nudged near it.
      Point f{nudge(a.x + b.x - e.x, k(rng)), nudge(a.y + b.y - e.y, k(rng))};
      ASSERT_EQ(incircle(a, b, e, f), static_cast<int>(CGAL::side_of_oriented_circle(kp(a), kp(b), kp(e), kp(f))));
      ASSERT_EQ(incircle(a, b, e, d), static_cast<int>(CGAL::side_of_oriented_circle(kp(a), kp(b), kp(e), kp(d))));
    }
    // Equal and nearly equal lengths: c mirrored over the bisector of ab.
    Point m{nudge(b.x, k(rng)), nudge(b.y, k(rng))};
    ASSERT_EQ(compare_sqlen(a, m, sqlen(a, m), b, a, sqlen(b, a)), exact_compare_sqlen(a, m, b, a));
    ASSERT_EQ(compare_sqlen(a, b, sqlen(a, b), d, c, sqlen(d, c)), exact_compare_sqlen(a, b, d, c));
    double s = 0.25;  // sin^2(30 degrees): the exact boundary an equilateral-like triangle meets
    ASSERT_EQ(skinny_at(a, b, e, s), exact_skinny_at(a, b, e, s));
    ASSERT_EQ(skinny_at(a, b, c, s), exact_skinny_at(a, b, c, s));
    double twice = std::fabs((b.x - a.x) * (e.y - a.y) - (b.y - a.y) * (e.x - a.x));
    ASSERT_EQ(area_above(a, b, e, twice), exact_area_above(a, b, e, twice));
    ASSERT_EQ(area_above(a, b, c, twice * 1e-20), exact_area_above(a, b, c, twice * 1e-20));
  }
  EXPECT_EQ(undecided_by_filter_would_be_wrong, 0);
}

// 1e-78 and 1e-155: the scales where the terms of the degree-4 (in-circle, skinny) and
// degree-2 (orientation) polynomials are subnormal but not zero, so rounding in double
// loses most of their digits; the filter must hand them to exact arithmetic.
INSTANTIATE_TEST_SUITE_P(Scales, NearDegenerate,
                         ::testing::Values(Scale{1, 0}, Scale{1, 1000}, Scale{1e-150, 0}, Scale{1e-300, 0},
                                           Scale{1e150, 0}, Scale{1e-3, 0.75}, Scale{1e-78, 0},
                                           Scale{1e-155, 0}));

// Underflow inside one product of a degree-4 predicate, beside terms that keep the
// permanent far above 2^-900. In-circle: d = 0, c = (0, m 2^-1074), so the minor
// b_x c_y is subnormal and rounds by up to half its last place, times the lift of
// a = (2^200, 2^200); b = (0.5, 2^100) lies near the circle through d and a that
// touches the y axis at d, so c is about as near it and the other minor's term
// cancels the first. Without the underflow term the filter decided 20 of these
// 78 the wrong way.
TEST(Predicates, UnderflowInAMinorTimesALargeLift) {
  int checked = 0;
  for (int m = 1; m < 40; ++m)
    for (double side : {1.0, -1.0}) {
      Point a{0x1p200, 0x1p200}, b{0.5, side * 0x1p100};
      const Point c{0, m * 0x1p-1074}, d{0, 0};
      if (CGAL::orientation(kp(a), kp(b), kp(c)) == CGAL::RIGHT_TURN) std::swap(a, b);
      ASSERT_EQ(incircle(a, b, c, d), static_cast<int>(CGAL::side_of_oriented_circle(kp(a), kp(b), kp(c), kp(d))))
          << "m = " << m << ", side " << side;
      ++checked;
    }
  EXPECT_EQ(checked, 78);
  // The same shape at random: a on the diagonal at 2^0 to 2^300, b near the circle
  // through d and a that touches the y axis at d, c a few subnormal units up from d
  // (some of them times up to 2^40) and off it by up to 1e-300. Without the underflow
  // term the filter got 373 of these wrong.
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> scale(0, 300), shift(-20, 20), units(1, 64), lift(0, 40);
  std::uniform_real_distribution<double> off(-1e-300, 1e-300);
  const double bases[] = {0.5, 0.25, 1.0, 3.0};
  for (int trial = 0; trial < 20000; ++trial) {
    const double h = std::ldexp(1.0, scale(rng));
    const double bx = bases[trial % 4] * std::ldexp(1.0, shift(rng));
    const double by = (trial % 8 < 4 ? 1 : -1) * std::sqrt(std::max(2 * h * bx - bx * bx, 0.0));
    Point a{h, h}, b{bx, by};
    const Point c{trial % 3 == 0 ? off(rng) : 0.0, std::ldexp(units(rng), lift(rng) - 1074)}, d{0, 0};
    const CGAL::Orientation o = CGAL::orientation(kp(a), kp(b), kp(c));
    if (o == CGAL::COLLINEAR) continue;
    if (o == CGAL::RIGHT_TURN) std::swap(a, b);
    ASSERT_EQ(incircle(a, b, c, d), static_cast<int>(CGAL::side_of_oriented_circle(kp(a), kp(b), kp(c), kp(d))))
        << "trial " << trial;
  }
}

// The skinny test at an apex between a side of about 2^-520 (its square subnormal,
// a few digits) and one of 2^100 to 2^400 at about theta = 30 degrees: the small-angle
// test of two input segments (Quality's wedge) asks exactly this. Without the
// underflow term the filter decided about 9 % of these the wrong way.
TEST(Predicates, UnderflowInASquareTimesALargeOne) {
  std::mt19937_64 rng(40);
  std::uniform_real_distribution<double> unit(1, 2), turn(-1e-3, 1e-3);
  std::uniform_int_distribution<int> small(520, 536), large(100, 400);
  const double s = 0.25, pi = std::acos(-1.0);
  for (int trial = 0; trial < 20000; ++trial) {
    const double r = std::ldexp(unit(rng), -small(rng)), angle = pi / 6 * (1 + turn(rng));
    const Point o{0, 0}, near{r * std::cos(angle), r * std::sin(angle)}, far{std::ldexp(1.0, large(rng)), 0};
    ASSERT_EQ(skinny_at(o, near, far, s), exact_skinny_at(o, near, far, s)) << "trial " << trial;
    ASSERT_EQ(skinny_at(o, far, near, s), exact_skinny_at(o, far, near, s)) << "trial " << trial;
  }
}

TEST(Predicates, ExactTiesAreZero) {
  // (3,4), (5,0), (4,-3), (-5,0) lie on the circle of radius 5.
  EXPECT_EQ(incircle({5, 0}, {3, 4}, {-5, 0}, {4, -3}), 0);
  EXPECT_EQ(incircle({5, 0}, {3, 4}, {-5, 0}, {4, -2.9999999999999996}), 1);
  EXPECT_EQ(orient({0, 0}, {1, 1}, {3, 3}), 0);
  EXPECT_EQ(orient({0.1, 0.1}, {0.2, 0.2}, {0.3, 0.3}), static_cast<int>(CGAL::orientation(K::Point_2(0.1, 0.1), K::Point_2(0.2, 0.2), K::Point_2(0.3, 0.3))));
  EXPECT_EQ(compare_sqlen({0, 0}, {3, 4}, 25, {1, 1}, {6, 1}, 25), 0);
  // 0.1 is not 1/10: |(0.1, 0.2)|^2 and |(0.2, 0.1)|^2 are still equal; 0.3 - 0.1 vs 0.2 is not.
  EXPECT_EQ(compare_sqlen({0, 0}, {0.1, 0.2}, sqlen({0, 0}, {0.1, 0.2}), {0, 0}, {0.2, 0.1}, sqlen({0, 0}, {0.2, 0.1})), 0);
  EXPECT_EQ(compare_sqlen({0.1, 0}, {0.3, 0}, sqlen({0.1, 0}, {0.3, 0}), {0, 0}, {0.2, 0}, sqlen({0, 0}, {0.2, 0})),
            exact_compare_sqlen({0.1, 0}, {0.3, 0}, {0, 0}, {0.2, 0}));
  EXPECT_TRUE(sqlen_below({0, 0}, {0.5, 0}, 0.75));
  EXPECT_FALSE(sqlen_below({0, 0}, {0.75, 0}, 0.75));
}

}  // namespace
}  // namespace lepp::fast
