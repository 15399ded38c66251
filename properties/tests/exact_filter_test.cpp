// SPDX-License-Identifier: GPL-3.0-or-later
// The certifier's first filter (properties/certify/src/exact.h, ErrorBounded): whenever
// it decides a sign, the sign is the exact one, on cases built to sit at its edge:
// points a few ulps off a line, products in the subnormal range, values near overflow.
// And it does decide the plain cases, or it would only cost time.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "exact.h"

namespace lepp::certify::exact {
namespace {

// The orientation determinant and a dot product, as the certifier's predicates write them.
template <class NT>
NT orientation(const Point& a, const Point& b, const Point& c) {
  return (NT(b.x) - NT(a.x)) * (NT(c.y) - NT(a.y)) - (NT(b.y) - NT(a.y)) * (NT(c.x) - NT(a.x));
}
template <class NT>
NT sin2_test(const Point& o, const Point& p, const Point& q, double s) {
  NT ux = NT(p.x) - NT(o.x), uy = NT(p.y) - NT(o.y), vx = NT(q.x) - NT(o.x), vy = NT(q.y) - NT(o.y);
  NT cross = ux * vy - uy * vx;
  return CGAL::abs(cross) * CGAL::abs(cross) - NT(s) * (ux * ux + uy * uy) * (vx * vx + vy * vy);
}

int exact_sign(const CGAL::Mpzf& v) { return static_cast<int>(CGAL::sign(v)); }

struct Tally {
  int decided = 0, cases = 0;
};

// Checks one case: a decided sign must be the exact sign.
void check(Tally& tally, int filtered, int exact, const char* what, const Point& a, const Point& b, const Point& c) {
  ++tally.cases;
  if (filtered == 2) return;
  ++tally.decided;
  ASSERT_EQ(filtered, exact) << what << " decided wrongly at (" << a.x << ", " << a.y << ") (" << b.x << ", " << b.y << ") ("
                             << c.x << ", " << c.y << ")";
}

// c on the line ab (rounded), then moved by k ulps in x and y: the determinant is zero or tiny.
Point near_line(std::mt19937_64& rng, const Point& a, const Point& b) {
  std::uniform_real_distribution<double> t(-0.5, 1.5);
  std::uniform_int_distribution<int> k(-3, 3);
  const double s = t(rng);
  Point c{a.x + s * (b.x - a.x), a.y + s * (b.y - a.y)};
  for (int i = k(rng); i != 0; i += i > 0 ? -1 : 1) c.x = std::nextafter(c.x, i > 0 ? INFINITY : -INFINITY);
  for (int i = k(rng); i != 0; i += i > 0 ? -1 : 1) c.y = std::nextafter(c.y, i > 0 ? INFINITY : -INFINITY);
  return c;
}

TEST(ExactFilter, DecidedSignsAreExactNearDegeneracyAtEveryScale) {
  std::mt19937_64 rng(20261206);
  std::uniform_real_distribution<double> unit(-1, 1);
  Tally near, general, normal_range;  // normal_range: general cases whose products stay normal doubles
  // Scales from subnormal products to products near overflow (2^511 squared twice overflows).
  for (int exponent : {-1070, -1060, -1030, -600, -500, -20, 0, 30, 250, 500, 511}) {
    for (int i = 0; i < 3000; ++i) {
      const Point a{std::ldexp(unit(rng), exponent), std::ldexp(unit(rng), exponent)};
      const Point b{std::ldexp(unit(rng), exponent), std::ldexp(unit(rng), exponent)};
      const Point c = near_line(rng, a, b);
      const Point d{std::ldexp(unit(rng), exponent), std::ldexp(unit(rng), exponent)};
      check(near, orientation<ErrorBounded>(a, b, c).sign_or_undecided(), exact_sign(orientation<CGAL::Mpzf>(a, b, c)),
            "orientation near a line", a, b, c);
      const int decided_before = general.decided;
      check(general, orientation<ErrorBounded>(a, b, d).sign_or_undecided(), exact_sign(orientation<CGAL::Mpzf>(a, b, d)),
            "orientation", a, b, d);
      if (exponent >= -500 && exponent <= 500) {  // products of two coordinates stay normal
        ++normal_range.cases;
        normal_range.decided += general.decided - decided_before;
      }
      // sin^2 of the angle at a against 1/4 (30 degrees): exact on the 30-degree ray too.
      const Point e{a.x + (b.x - a.x) * 0.8660254037844386 - (b.y - a.y) * 0.5, a.y + (b.x - a.x) * 0.5 + (b.y - a.y) * 0.8660254037844386};
      check(near, sin2_test<ErrorBounded>(a, b, e, 0.25).sign_or_undecided(), exact_sign(sin2_test<CGAL::Mpzf>(a, b, e, 0.25)),
            "sin^2 against 1/4 near 30 degrees", a, b, e);
      if (HasFatalFailure()) return;
    }
  }
  // The filter decides most general cases where products are normal doubles (else it
  // only costs time; below that range the interval and exact paths decide) and leaves
  // the degenerate ones open often enough that the exact path is exercised.
  EXPECT_GT(normal_range.decided, normal_range.cases * 99 / 100);
  EXPECT_LT(near.decided, near.cases);
}

// TriangleShape (the index's shared filter over a triangle) answers as acute_angle_sin2_below
// at the two corners that do not face a longest side, as angle_over_120 at every corner,
// and as the exact sign of |orient| - 2 bound for the area, on triangles with an angle a
// few ulps from 30 or 120 degrees (where the filter must leave the sign open) and general
// ones, at every scale; its squared lengths order the sides as compare_squared_length does.
TEST(ExactFilter, TriangleShapeAnswersAsTheFullPredicates) {
  std::mt19937_64 rng(40);
  std::uniform_real_distribution<double> unit(-1, 1);
  const double s30 = 0.25, s_below = std::nextafter(0.25, 0.0), s_above = std::nextafter(0.25, 1.0);
  int corners = 0, near = 0, areas = 0, obtuse = 0;
  for (int exponent : {-1070, -1030, -500, -20, 0, 30, 250, 500, 511}) {
    for (int i = 0; i < 2000; ++i) {
      Point a{std::ldexp(unit(rng), exponent), std::ldexp(unit(rng), exponent)};
      Point b{std::ldexp(unit(rng), exponent), std::ldexp(unit(rng), exponent)};
      // c at 30 or 120 degrees from ab seen from a (rounded, then moved by ulps), or anywhere.
      const double cosine = i % 4 == 3 ? -0.5 : 0.8660254037844386, sine = i % 4 == 3 ? 0.8660254037844386 : 0.5;
      Point c = i % 2 ? Point{a.x + (b.x - a.x) * cosine - (b.y - a.y) * sine, a.y + (b.x - a.x) * sine + (b.y - a.y) * cosine}
                      : Point{std::ldexp(unit(rng), exponent), std::ldexp(unit(rng), exponent)};
      std::uniform_int_distribution<int> ulps(-3, 3);
      if (i % 2)
        for (double* v : {&c.x, &c.y})
          for (int k = ulps(rng); k != 0; k += k > 0 ? -1 : 1) *v = std::nextafter(*v, k > 0 ? INFINITY : -INFINITY);
      const int o = orient(a, b, c);
      if (o == 0) continue;
      if (o < 0) std::swap(b, c);
      const Point* x[3] = {&a, &b, &c};
      int longest = 0;  // side i runs x[i] -> x[i + 1]
      for (int k = 1; k < 3; ++k)
        if (compare_squared_length(*x[k], *x[(k + 1) % 3], *x[longest], *x[(longest + 1) % 3]) > 0) longest = k;
      const TriangleShape fused(a, b, c);
      for (int k = 0; k < 3; ++k) {
        const int filtered = (fused.squared_lengths()[static_cast<std::size_t>(k)] - fused.squared_lengths()[static_cast<std::size_t>((k + 1) % 3)])
                                 .sign_or_undecided();
        if (filtered != 2) ASSERT_EQ(filtered, compare_squared_length(*x[k], *x[(k + 1) % 3], *x[(k + 1) % 3], *x[(k + 2) % 3]));
      }
      for (int k = 0; k < 3; ++k) {
        ASSERT_EQ(fused.angle_over_120_at(k), angle_over_120(*x[k], *x[(k + 1) % 3], *x[(k + 2) % 3])) << "over 120 at corner " << k;
        obtuse += fused.angle_over_120_at(k);
      }
      // The area against bounds around its own value (a rounded half of the doubled area).
      const double half = std::abs(orientation<double>(a, b, c)) / 2;
      for (double bound : {half, std::nextafter(half, 0.0), std::nextafter(half, INFINITY), half / 3, half * 3}) {
        const int exact = exact_sign(CGAL::abs(orientation<CGAL::Mpzf>(a, b, c)) - (CGAL::Mpzf(bound) + CGAL::Mpzf(bound)));
        ASSERT_EQ(fused.doubled_area_above(bound), exact > 0) << "area against " << bound;
        ++areas;
      }
      for (int k = 0; k < 3; ++k) {
        if (k == (longest + 2) % 3) continue;
        for (double s : {s30, s_below, s_above, 0.0669872981077807, 0.74}) {
          ++corners;
          near += i % 2;
          ASSERT_EQ(fused.sin2_below(k, s), acute_angle_sin2_below(*x[k], *x[(k + 1) % 3], *x[(k + 2) % 3], s))
              << "corner " << k << " of (" << a.x << ", " << a.y << ") (" << b.x << ", " << b.y << ") (" << c.x << ", " << c.y
              << ") against sin^2 " << s;
        }
      }
    }
  }
  EXPECT_GT(corners, 50000);
  EXPECT_GT(areas, 50000);
  EXPECT_GT(obtuse, 2000);
  EXPECT_GT(near, 20000);
}

TEST(ExactFilter, ExactZeroOnlyWithoutRounding) {
  const Point a{1, 1}, b{2, 2}, c{3, 3};
  // Products are never trusted to be zero: the determinant of collinear points is left open...
  EXPECT_EQ(orientation<ErrorBounded>(a, b, c).sign_or_undecided(), 2);
  // ...and decided by sign(), exactly.
  EXPECT_EQ(sign([&](auto z) { return orientation<decltype(z)>(a, b, c); }), 0);
  // A difference of equal doubles is exactly zero.
  EXPECT_EQ((ErrorBounded(0.1) - ErrorBounded(0.1)).sign_or_undecided(), 0);
}

TEST(ExactFilter, OverflowIsLeftToTheExactPath) {
  const Point a{0, 0}, b{0x1p600, 0x1p600}, c{0x1p600, -0x1p600};  // products of 2^1200 overflow
  EXPECT_EQ(orientation<ErrorBounded>(a, b, c).sign_or_undecided(), 2);
  EXPECT_EQ(sign([&](auto z) { return orientation<decltype(z)>(a, b, c); }), -1);
}

}  // namespace
}  // namespace lepp::certify::exact
