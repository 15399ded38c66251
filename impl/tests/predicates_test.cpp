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

#include "exact_doubles.h"
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

// The exact path's doubles (exact_doubles.h) answer only when every step was exact;
// each kind of inexact step must leave the case to Mpzf (2), never a sign.
TEST(ExactDoubles, EveryInexactStepIsUndecided) {
  using detail::compare_sqlen_in_doubles;
  // Exact everywhere: grid ties and cocircular grid points, answered in doubles.
  EXPECT_EQ(compare_sqlen_in_doubles({1, 1}, {4, 5}, {0, 0}, {0, 5}), 0);
  EXPECT_EQ(detail::incircle_in_doubles({5, 0}, {3, 4}, {-5, 0}, {4, -3}), 0);
  EXPECT_EQ(detail::orient_in_doubles({0, 0}, {1, 1}, {3, 3}), 0);
  EXPECT_EQ(detail::dot_sign_in_doubles({0, 0}, {1, 0}, {0, 7}), 0);
  EXPECT_EQ(detail::skinny_sign_in_doubles({0, 0}, {1, 0}, {1, 1}, 0.5), 0);  // 45 degrees, sin^2 = 1/2
  EXPECT_EQ(detail::area_sign_in_doubles({0, 0}, {2, 0}, {0, 3}, 6), 0);
  EXPECT_EQ(detail::sqlen_below_in_doubles({0, 0}, {3, 4}, 5), 0);
  // A difference rounded: 1 - (-2^-60) is 1 in doubles.
  EXPECT_EQ(compare_sqlen_in_doubles({1, 0}, {-0x1p-60, 0}, {1, 0}, {0, 0}), 2);
  // A square rounded: (1 + 2^-30)^2 needs 61 bits.
  EXPECT_EQ(compare_sqlen_in_doubles({0, 0}, {1 + 0x1p-30, 0}, {0, 0}, {1 + 0x1p-30 - 0x1p-52, 0}), 2);
  // A square below the range: 2^-600 squared vanishes beside 1, fma's error term with it.
  EXPECT_EQ(compare_sqlen_in_doubles({0, 0}, {1, 0x1p-600}, {0, 0}, {1, 0}), 2);
  // A sum rounded: 1 + 2^-60 against 1.
  EXPECT_EQ(compare_sqlen_in_doubles({0, 0}, {1, 0x1p-30}, {0, 0}, {1, 0}), 2);
  // An overflow: the sum's check sees NaN.
  EXPECT_EQ(detail::orient_in_doubles({-1e308, 0}, {1e308, 1}, {0, 2}), 2);
  // The last sum rounded: 1 + 2^-60.
  EXPECT_EQ(detail::dot_sign_in_doubles({0, 0}, {1, 0x1p-30}, {1, 0x1p-30}), 2);
}

// The length comparisons before Mpzf (exact_doubles.h): by dominance, a sign only where
// both sorted component comparisons agree (or one ties); as a sum of expansions, a sign
// where every factor is in range; always the exact one. The near-ties across scales of
// the fuzzers' ulp clusters are decided without Mpzf.
TEST(ExactDoubles, LengthsByDominanceAgreeWithExactArithmetic) {
  using detail::compare_sqlen_by_dominance;
  auto q_compare = [](const Point& a, const Point& b, const Point& c, const Point& d) {
    const Q abx = Q(b.x) - Q(a.x), aby = Q(b.y) - Q(a.y), cdx = Q(d.x) - Q(c.x), cdy = Q(d.y) - Q(c.y);
    const Q diff = abx * abx + aby * aby - cdx * cdx - cdy * cdy;
    return diff > 0 ? 1 : diff < 0 ? -1 : 0;
  };
  // A fuzzer's case: 1.5 and 1.5 * 2^-150 against 1.5 and 1.5 * 2^-151, the components swapped.
  EXPECT_EQ(compare_sqlen_by_dominance({1.5, 0}, {0, 0x1.8p-150}, {0, 0x1.8p-151}, {1.5, 0}), 1);
  EXPECT_EQ(compare_sqlen_by_dominance({0, 0}, {3, 4}, {0, 0}, {4, -3}), 0);   // the same components
  EXPECT_EQ(compare_sqlen_by_dominance({0, 0}, {3, 4}, {0, 0}, {5, 0}), 2);    // 5 > 4 but 0 < 3
  EXPECT_EQ(compare_sqlen_by_dominance({0, 0}, {1, 1}, {0, 0}, {1, 2}), -1);   // one ties, one less
  EXPECT_EQ(compare_sqlen_by_dominance({1, 0}, {-0x1p-60, 0}, {0, 0}, {1, 0}), 2);  // a difference rounded
  std::mt19937_64 rng(41);
  std::uniform_int_distribution<int> scale(-1074, 40), pick(0, 5);
  std::uniform_real_distribution<double> unit(1, 2);
  const double shared[3] = {1.5, 0x1.8p-150, 3.0};
  auto coordinate = [&]() {
    const int k = pick(rng);  // a shared value (ties), zero, or a value of any scale and sign
    if (k < 3) return shared[k];
    if (k == 3) return 0.0;
    return (k == 4 ? 1 : -1) * std::ldexp(unit(rng), scale(rng));
  };
  // As sums of expansions: differences rounded (1.125 - 2^-160), and factors out of range.
  EXPECT_EQ(detail::compare_sqlen_by_expansion({0, 0x1.8p-160}, {1.5, 1.125}, {1.5, 1.125}, {0, 0x1.8p-159}), 1);
  EXPECT_EQ(detail::compare_sqlen_by_expansion({0, 0}, {1 + 0x1p-30, 0}, {0, 0}, {1 + 0x1p-30 - 0x1p-52, 0}), 1);
  EXPECT_EQ(detail::compare_sqlen_by_expansion({1, 0}, {-0x1p-60, 0}, {-0x1p-60, 0}, {1, 0}), 0);
  // u^2 against v^2 + w^2, apart by less than u^2's rounding error (fma's term decides).
  const double u = 0x1.2194b2b8fe000p+0, v = 0x1.06be000000000p+0, w = 0x1.e702506f59beep-2;
  EXPECT_EQ(detail::compare_sqlen_by_expansion({0, 0}, {u, 0}, {0, 0}, {v, w}), 1);
  EXPECT_EQ(detail::compare_sqlen_by_expansion({0, 0}, {v, w}, {0, 0}, {u, 0}), -1);
  // (p - q)^2 = (h + l)^2 against h^2 + z^2, apart by less than the rounding of 2hl.
  const double p = 0x1.442f7dbc496ccp+0, q = -0x1.d69964a23d596p-55, z = 0x1.869755127fb44p-27;
  EXPECT_EQ(detail::compare_sqlen_by_expansion({q, 0}, {p, 0}, {0, 0}, {p, z}), 1);
  // A tie that only l^2's rounding keeps: b - a = (2^50 - m, r) with m = r^2 / 2^51 (TwoSum:
  // h = 2^50, l = -m, whose square m^2 is no double) against (2^50, m): (h + l)^2 + r^2 =
  // h^2 + 2hl + l^2 + r^2 = h^2 + m^2 exactly, since 2hl = -r^2. The other side's m^2 is
  // its first term's rounding and error, this side's its third's: drop l^2's error and the
  // tie becomes a sign.
  const double r = 0x1p19 + 1, m = r * r / 0x1p51;
  EXPECT_EQ(detail::compare_sqlen_by_expansion({m, 0}, {0x1p50, r}, {0, 0}, {0x1p50, m}), 0);
  EXPECT_EQ(detail::compare_sqlen_exact({m, 0}, {0x1p50, r}, {0, 0}, {0x1p50, m}), 0);
  EXPECT_EQ(detail::compare_sqlen_by_expansion({0, 0}, {1, 0x1p-600}, {0, 0}, {1, 0}), 2);
  EXPECT_EQ(detail::compare_sqlen_by_expansion({0, 0}, {0x1p500, 0}, {0, 0}, {1, 0}), 2);
  int decided = 0, by_expansion = 0;
  for (int trial = 0; trial < 50000; ++trial) {
    const Point a{coordinate(), coordinate()}, b{coordinate(), coordinate()}, c{coordinate(), coordinate()},
        d{coordinate(), coordinate()};
    const int exact = q_compare(a, b, c, d);
    if (const int s = compare_sqlen_by_dominance(a, b, c, d); s != 2) {
      ++decided;
      ASSERT_EQ(s, exact) << "trial " << trial;
    }
    if (const int s = detail::compare_sqlen_by_expansion(a, b, c, d); s != 2) {
      ++by_expansion;
      ASSERT_EQ(s, exact) << "trial " << trial;
    }
    ASSERT_EQ(detail::compare_sqlen_exact(a, b, c, d), exact) << "trial " << trial;
  }
  EXPECT_GT(decided, 1000);  // the shortcut is reached: 1,872 of these 50,000 with this seed
  EXPECT_GT(by_expansion, 1000) << by_expansion;
}

// The orientation as an exact sum plus a bounded rest (exact_doubles.h), before Mpzf: a
// sign only where it is the exact one. The family is the sliver clause's: points of size
// about 1 (some on a line through the origin), against clusters a few units of 2^e wide
// at the origin, e down to the subnormals, where no double holds a product's error.
TEST(ExactDoubles, OrientationByExpansionAgreesWithExactArithmetic) {
  // Decided: differences h = 2, l = 2^-1074 (from the subnormal a) and 2^-400 + 2^-1074:
  // the doubles' difference is rounded, the products of the h parts decide, far beyond
  // the left-out ones' bound.
  const Point far{2, 1}, a{-0x1p-1074, 0}, above{0x1p-400, 0x1p-399};
  EXPECT_EQ(detail::orient_in_doubles(a, far, above), 2);
  EXPECT_EQ(detail::orient_by_expansion(a, far, above), static_cast<int>(CGAL::orientation(kp(a), kp(far), kp(above))));
  // Undecided: the products in range cancel exactly (b on the line of slope 1/2 through
  // the origin, a and c in the cluster), and only the left-out ones hold the sign.
  const Point ca{-0x1p-1063, 0x1p-1064}, cb{0x1.0624dd2f1a9fcp+0, 0x1.0624dd2f1a9fcp-1}, cc{0, 0x1p-1063};
  EXPECT_EQ(detail::orient_by_expansion(ca, cb, cc), 2);
  EXPECT_EQ(detail::orient_exact(ca, cb, cc), static_cast<int>(CGAL::orientation(kp(ca), kp(cb), kp(cc))));
  // Far beyond the range on both sides: no decision.
  EXPECT_EQ(detail::orient_by_expansion({0, 0}, {0x1p600, 1}, {1, 0x1p600}), 2);
  std::mt19937_64 rng(43);
  std::uniform_int_distribution<int> small(-6, 6), pick(0, 7), ulps(-3, 3);
  std::uniform_real_distribution<double> unit(0.5, 2);
  const int exponents[] = {-1074, -1066, -1000, -700, -481, -479};
  int decided = 0, beyond_doubles = 0, undecided = 0;
  for (int trial = 0; trial < 60000; ++trial) {
    const int e = exponents[pick(rng) % 6];
    const double sx = unit(rng), sy = unit(rng) * (pick(rng) < 4 ? 1 : -1);
    auto pt = [&]() -> Point {
      switch (pick(rng)) {
        case 0: case 1: case 2:  // the cluster at the origin
          return {std::ldexp(small(rng), e), std::ldexp(small(rng), e)};
        case 3:  // on (or a few ulps off) the line through the origin along (sx, sy)
          return {nudge(sx, ulps(rng)), nudge(sy, ulps(rng))};
        case 4: {  // that line at another distance, a power of two off (exact) and nudged
          const int k = small(rng);
          return {nudge(std::ldexp(sx, k), ulps(rng)), std::ldexp(sy, k)};
        }
        case 5:
          return {sx, sy};
        default:  // anywhere of size about 1
          return {unit(rng) - 1.25, unit(rng) - 1.25};
      }
    };
    const Point p = pt(), q = pt(), r = pt();
    const int exact = static_cast<int>(CGAL::orientation(kp(p), kp(q), kp(r)));
    SCOPED_TRACE(::testing::Message() << "trial " << trial << std::hexfloat << ": " << p.x << " " << p.y << " | "
                                      << q.x << " " << q.y << " | " << r.x << " " << r.y);
    if (const int s = detail::orient_by_expansion(p, q, r); s != 2) {
      ++decided;
      ASSERT_EQ(s, exact);
      beyond_doubles += detail::orient_in_doubles(p, q, r) == 2;
    } else {
      ++undecided;
    }
    ASSERT_EQ(orient(p, q, r), exact);
  }
  // Reached where the doubles alone cannot decide, and left undecided too (without
  // orient_exact's scaling first): 44,805 decided, 42,037 of them beyond the doubles, and
  // 15,195 undecided of these 60,000 with this seed.
  EXPECT_GT(beyond_doubles, 20000) << decided;
  EXPECT_GT(undecided, 5000);
}

// Exact signs, zero included, for the predicates whose callers see only a test.
int q_sign(const Q& v) { return v > 0 ? 1 : v < 0 ? -1 : 0; }
int q_skinny_sign(const Point& o, const Point& p, const Point& q, double s) {
  Q ux = Q(p.x) - Q(o.x), uy = Q(p.y) - Q(o.y), wx = Q(q.x) - Q(o.x), wy = Q(q.y) - Q(o.y);
  Q cross = ux * wy - uy * wx;
  return q_sign(Q(s) * (ux * ux + uy * uy) * (wx * wx + wy * wy) - cross * cross);
}
int q_area_sign(const Point& a, const Point& b, const Point& c, double twice) {
  Q cross = (Q(b.x) - Q(a.x)) * (Q(c.y) - Q(a.y)) - (Q(b.y) - Q(a.y)) * (Q(c.x) - Q(a.x));
  if (cross < 0) cross = -cross;
  return q_sign(cross - Q(twice));
}
int q_dot_sign(const Point& v, const Point& a, const Point& b) {
  return q_sign((Q(a.x) - Q(v.x)) * (Q(b.x) - Q(v.x)) + (Q(a.y) - Q(v.y)) * (Q(b.y) - Q(v.y)));
}
int q_sqlen_below_sign(const Point& a, const Point& b, double floor) {
  Q dx = Q(b.x) - Q(a.x), dy = Q(b.y) - Q(a.y);
  return q_sign(Q(floor) * Q(floor) - (dx * dx + dy * dy));
}
// sin^2 of the smallest angle is cross^2 / M, M the largest product of two squared sides.
Q q_sin2(const Point* t) {
  auto l = [&](int i, int j) -> Q {  // a Q, not gmpxx's expression of locals
    Q dx = Q(t[j].x) - Q(t[i].x), dy = Q(t[j].y) - Q(t[i].y);
    return dx * dx + dy * dy;
  };
  Q cross = (Q(t[1].x) - Q(t[0].x)) * (Q(t[2].y) - Q(t[0].y)) - (Q(t[1].y) - Q(t[0].y)) * (Q(t[2].x) - Q(t[0].x));
  Q la = l(0, 1), lb = l(0, 2), lc = l(1, 2);
  Q m = la * lb;
  if (la * lc > m) m = la * lc;
  if (lb * lc > m) m = lb * lc;
  return cross * cross / m;
}

// Points a few units of 2^e apart (e down to the subnormals), several scales in one
// call: the exact path reruns the filter at scale (tiny points), tries doubles, then
// Mpzf. Every predicate's exact sign, zero included, against rationals.
TEST(Predicates, TinyClustersAgreeWithExactArithmetic) {
  std::mt19937_64 rng(40);
  std::uniform_int_distribution<int> small(-4, 4), pick(0, 5);
  const int exponents[] = {-1074, -1070, -1050, -800, -540, -300, -60, 0};
  int zeros = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const int e1 = exponents[pick(rng)], e2 = exponents[pick(rng) + 2];
    auto pt = [&]() {
      const int e = pick(rng) < 4 ? e1 : e2;  // mostly one scale, sometimes another
      return Point{std::ldexp(small(rng), e), std::ldexp(small(rng), e)};
    };
    const Point a = pt(), b = pt(), c = pt(), d = pt();
    SCOPED_TRACE(::testing::Message() << std::hexfloat << a.x << " " << a.y << " | " << b.x << " " << b.y << " | "
                                      << c.x << " " << c.y << " | " << d.x << " " << d.y);
    ASSERT_EQ(orient(a, b, c), static_cast<int>(CGAL::orientation(kp(a), kp(b), kp(c))));
    if (orient(a, b, c) > 0)
      ASSERT_EQ(incircle(a, b, c, d), static_cast<int>(CGAL::side_of_oriented_circle(kp(a), kp(b), kp(c), kp(d))));
    ASSERT_EQ(compare_sqlen(a, b, sqlen(a, b), c, d, sqlen(c, d)), exact_compare_sqlen(a, b, c, d));
    ASSERT_EQ(dot_sign(a, b, c), q_dot_sign(a, b, c));
    for (double s : {0.25, 0.5, 0.1}) ASSERT_EQ(skinny_sign(a, b, c, s), q_skinny_sign(a, b, c, s));
    const double twice = std::fabs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
    ASSERT_EQ(area_sign(a, b, d, twice), q_area_sign(a, b, d, twice));
    ASSERT_EQ(area_sign(a, b, c, twice), q_area_sign(a, b, c, twice));
    const double floor = std::sqrt(sqlen(c, d));
    ASSERT_EQ(sqlen_below_sign(a, b, floor), q_sqlen_below_sign(a, b, floor));
    const Point t1[3] = {a, b, c}, t2[3] = {a, c, d};
    if (orient(a, b, c) != 0 && orient(a, c, d) != 0) {
      const Q s1 = q_sin2(t1), s2 = q_sin2(t2);
      ASSERT_EQ(detail::compare_sin2_exact(t1, t2), s1 < s2 ? -1 : s1 > s2 ? 1 : 0);
    }
    zeros += exact_compare_sqlen(a, b, c, d) == 0;
  }
  EXPECT_GT(zeros, 0);  // the family holds exact ties
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
