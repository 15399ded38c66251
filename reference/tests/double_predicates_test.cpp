// SPDX-License-Identifier: GPL-3.0-or-later
// The reference's exact predicates on double coordinates (src/double_predicates.h):
// each answer against GMP rationals (an oracle independent of the filter and of
// CGAL::Mpzf), at the boundaries where a filter goes wrong: exact ties, values
// differing in the last bit, subnormal coordinates whose squares underflow and
// huge ones whose squares overflow the doubles.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "../src/double_predicates.h"

namespace {

using lepp::Point;
using lepp::reference::detail::compare_squared_lengths;
using lepp::reference::detail::compare_squared_lengths_exact;
using lepp::reference::detail::skinny_at;

constexpr double kTiny = std::numeric_limits<double>::denorm_min();  // 2^-1074

int sign(const mpq_class& q) { return sgn(q); }

mpq_class squared(const Point& a, const Point& b) {
  const mpq_class dx = mpq_class(a.x) - mpq_class(b.x), dy = mpq_class(a.y) - mpq_class(b.y);
  return dx * dx + dy * dy;
}

int oracle_compare(const Point& a, const Point& b, const Point& c, const Point& d) {
  return sign(squared(a, b) - squared(c, d));
}

bool oracle_skinny(const Point& o, const Point& b, const Point& c, double sin2) {
  const mpq_class ux = mpq_class(b.x) - mpq_class(o.x), uy = mpq_class(b.y) - mpq_class(o.y);
  const mpq_class vx = mpq_class(c.x) - mpq_class(o.x), vy = mpq_class(c.y) - mpq_class(o.y);
  const mpq_class cross = ux * vy - uy * vx;
  return cross * cross < mpq_class(sin2) * (ux * ux + uy * uy) * (vx * vx + vy * vy);
}

// The filtered comparison, its exact path and the oracle agree, both ways round.
void expect_compare(const Point& a, const Point& b, const Point& c, const Point& d, int expected) {
  ASSERT_EQ(oracle_compare(a, b, c, d), expected) << "the case is not what it claims";
  EXPECT_EQ(compare_squared_lengths(a, b, c, d), expected);
  EXPECT_EQ(compare_squared_lengths(c, d, a, b), -expected);
  EXPECT_EQ(compare_squared_lengths_exact(a, b, c, d), expected);
}

void expect_skinny(const Point& o, const Point& b, const Point& c, double sin2, bool expected) {
  ASSERT_EQ(oracle_skinny(o, b, c, sin2), expected) << "the case is not what it claims";
  EXPECT_EQ(skinny_at(o, b, c, sin2), expected);
  EXPECT_EQ(skinny_at(o, c, b, sin2), expected);  // the sign of the cross product does not matter
}

TEST(ReferenceDoubleLengths, ExactTiesAtEveryScale) {
  for (double s : {1.0, 0x1p-30, kTiny, 0x1p-1000, 0x1p+990, 1e300 / 8}) {
    SCOPED_TRACE(s);
    // 3-4-5: |ab|^2 = |cd|^2 = 25 s^2, at s = 1e300/8 beyond the doubles.
    expect_compare({0, 0}, {3 * s, 4 * s}, {s, 0}, {6 * s, 0}, 0);
    expect_compare({2 * s, s}, {-s, 5 * s}, {0, 0}, {0, -5 * s}, 0);
  }
  // Ties whose squares are not doubles: (1 + 2^-52)^2 needs 105 bits.
  const double e = 1 + 0x1p-52;
  expect_compare({0, 0}, {e, 1}, {1, 0}, {0, -e}, 0);
  // Across the doubles' range: -1e308 to 1e308 overflows the difference itself.
  expect_compare({-1e308, 0}, {1e308, 0}, {0, 1e308}, {0, -1e308}, 0);
}

TEST(ReferenceDoubleLengths, LengthsDifferingInTheLastBit) {
  const double one_up = std::nextafter(1.0, 2.0);
  expect_compare({0, 0}, {one_up, 0}, {0, 0}, {1, 0}, 1);
  expect_compare({0, 0}, {1, 0x1p-30}, {0, 0}, {1, 0}, 1);  // 1 + 2^-60 against 1: the same double
  expect_compare({0, 0}, {1, 0x1p-30}, {0, 0}, {0x1p-30, 1}, 0);
  // Huge: the last bit of 1e300 and squares that overflow.
  expect_compare({0, 0}, {std::nextafter(1e300, 2e300), 0}, {0, 0}, {0, 1e300}, 1);
  expect_compare({-1e308, 0}, {1e308, 0}, {0, std::nextafter(1e308, 0.0)}, {0, -1e308}, 1);
  // Subnormal: one ulp of the smallest double, squares far below it.
  expect_compare({0, 0}, {3 * kTiny, 4 * kTiny}, {0, 0}, {5 * kTiny, kTiny}, -1);
  expect_compare({kTiny, 0}, {0, kTiny}, {0, 0}, {kTiny, 0}, 1);
}

// The filter's undecided cases are answered in doubles when every step was exact
// (exact_squared_length): each step that is not must send the case to Mpzf.
TEST(ReferenceDoubleLengths, UndecidedCasesTrustOnlyExactDoubleSteps) {
  // Exact everywhere: grid ties, answered in doubles.
  double l = 0;
  ASSERT_TRUE(lepp::reference::detail::exact_squared_length({0, 0}, {3, 4}, l));
  EXPECT_EQ(l, 25);
  expect_compare({1, 1}, {4, 5}, {0, 0}, {0, 5}, 0);
  // A difference rounded: 1 - (-2^-60) is 1 in doubles.
  expect_compare({1, 0}, {-0x1p-60, 0}, {1, 0}, {0, 0}, 1);
  // A square rounded: (1 + 2^-30)^2 needs 61 bits.
  expect_compare({0, 0}, {1 + 0x1p-30, 0}, {0, 0}, {1 + 0x1p-30 - 0x1p-52, 0}, 1);
  // The second square rounded, the first exact: (1 + 2^-51)^2 = 1 + 2^-50 + 2^-102
  // rounds to 1 + 2^-50, which 1^2 + (2^-25)^2 is exactly: a tie in doubles, not in fact.
  expect_compare({0, 0}, {0, 1 + 0x1p-51}, {0, 0}, {1, 0x1p-25}, 1);
  // A square below the doubles beside a length of 1: 2^-1200 vanishes and fma's
  // error term with it (the range guard), so 1 + 2^-1200 must not tie with 1.
  expect_compare({0, 0}, {1, 0x1p-600}, {0, 0}, {1, 0}, 1);
  expect_compare({0, 0}, {1, 0x1p-600}, {0, 0}, {0x1p-600, 1}, 0);
  // A sum rounded: 1 + 2^-60 against 1.
  expect_compare({0, 0}, {1, 0x1p-30}, {0, 0}, {1, 0}, 1);
}

TEST(ReferenceDoubleLengths, SquaresRoundedInTheSubnormalsAreNotTrusted) {
  // |ab|^2 = 2.6 * 2^-1074 rounds to 3 * 2^-1074; |cd|^2 = 2 * 1.45 * 2^-1074, each
  // square rounded to 2^-1074: in doubles ab looks longer by a whole unit, yet it is shorter.
  const double b = std::sqrt(2.6) * 0x1p-537, x = std::sqrt(1.45) * 0x1p-537;
  ASSERT_GT(b * b, x * x + x * x);
  expect_compare({0, 0}, {b, 0}, {0, 0}, {x, x}, -1);
}

TEST(ReferenceDoubleLengths, NearTiesAgreeWithTheOracle) {
  // Points near the unit circle a few ulps apart: their squared lengths differ
  // below the doubles' resolution, where the double values often order them wrongly.
  std::mt19937_64 rng(28);
  std::uniform_int_distribution<int> ulps(-8, 8);
  std::uniform_real_distribution<double> angle(0, 1.5);
  int ties = 0, wrong_in_doubles = 0;
  for (int k = 0; k < 20000; ++k) {
    const double t = angle(rng);
    auto near = [&](double v) { return v + ulps(rng) * 0x1p-53; };
    const Point o{0, 0}, p{near(std::cos(t)), near(std::sin(t))}, q{near(std::sin(t)), near(std::cos(t))};
    const int expected = oracle_compare(o, p, o, q);
    ties += expected == 0;
    const double lp = p.x * p.x + p.y * p.y, lq = q.x * q.x + q.y * q.y;
    wrong_in_doubles += lp != lq && (lp > lq ? 1 : -1) != expected;
    ASSERT_EQ(compare_squared_lengths(o, p, o, q), expected) << p.x << " " << p.y << " / " << q.x << " " << q.y;
  }
  EXPECT_GT(ties, 0);              // the family holds exact ties
  EXPECT_GT(wrong_in_doubles, 0);  // and pairs the doubles order wrongly, not only as ties
}

TEST(ReferenceSkinny, ExactTiesAreNotSkinnyAtEveryScale) {
  // The angle at o is 45 degrees: sin^2 = 1/2 exactly; skinny means strictly below.
  for (double s : {1.0, kTiny, 0x1p-600, 0x1p+600, 1e300}) {
    SCOPED_TRACE(s);
    expect_skinny({0, 0}, {s, 0}, {s, s}, 0.5, false);
    expect_skinny({0, 0}, {2 * s, 0}, {s, s}, 0.5, false);
  }
  expect_skinny({0, 0}, {1, 0}, {1, 1}, std::nextafter(0.5, 1.0), true);  // the threshold one bit above
  expect_skinny({0, 0}, {1, 0}, {1, 1}, std::nextafter(0.5, 0.0), false);
}

TEST(ReferenceSkinny, AnglesDifferingInTheLastBit) {
  const double one_up = std::nextafter(1.0, 2.0);
  expect_skinny({0, 0}, {1, 0}, {one_up, 1}, 0.5, true);   // just below 45 degrees
  expect_skinny({0, 0}, {1, 0}, {1, one_up}, 0.5, false);  // just above
  // Huge: 1e300 and the next double; the products overflow the doubles.
  const double big_up = std::nextafter(1e300, 2e300);
  expect_skinny({0, 0}, {1e300, 0}, {big_up, 1e300}, 0.5, true);
  expect_skinny({0, 0}, {1e300, 0}, {1e300, big_up}, 0.5, false);
  // Subnormal vectors one unit of 2^-1074 off the tie: 4-by-4 against 5-by-4.
  expect_skinny({0, 0}, {4 * kTiny, 0}, {5 * kTiny, 4 * kTiny}, 0.5, true);
  expect_skinny({0, 0}, {4 * kTiny, 0}, {4 * kTiny, 5 * kTiny}, 0.5, false);
}

TEST(ReferenceSkinny, NearTiesAgreeWithTheOracle) {
  // Angles of 30 degrees at random rotations, each coordinate moved up to 64 ulps:
  // cross^2 and sin2 |u|^2 |v|^2 differ near the doubles' resolution, where the
  // double values sometimes order them wrongly (strictly, not only as a tie).
  std::mt19937_64 rng(20);
  std::uniform_int_distribution<int> ulps(-64, 64);
  std::uniform_real_distribution<double> angle(0, 1);
  const double sin2 = 0.25, pi = std::acos(-1.0);
  int wrong_in_doubles = 0;
  for (int k = 0; k < 40000; ++k) {
    auto near = [&](double v) { return v + ulps(rng) * 0x1p-52 * v; };
    const double t = angle(rng);
    const Point o{0, 0}, b{near(std::cos(t)), near(std::sin(t))}, c{near(std::cos(t + pi / 6)), near(std::sin(t + pi / 6))};
    const bool expected = oracle_skinny(o, b, c, sin2);
    const double cross = b.x * c.y - b.y * c.x, lhs = cross * cross;
    const double rhs = sin2 * ((b.x * b.x + b.y * b.y) * (c.x * c.x + c.y * c.y));
    wrong_in_doubles += lhs != rhs && (lhs < rhs) != expected;
    ASSERT_EQ(skinny_at(o, b, c, sin2), expected) << b.x << " " << b.y << " / " << c.x << " " << c.y;
  }
  EXPECT_GT(wrong_in_doubles, 0);
}

// Lengths compared by their components (compare_lengths_by_components): a sign only
// where both sorted comparisons agree or one ties, always the oracle's; the ulp
// clusters' near-ties across scales decided without Mpzf.
TEST(ReferenceDoubleLengths, ComponentsDecideOnlyWhereTheyAgree) {
  using lepp::reference::detail::compare_lengths_by_components;
  EXPECT_EQ(compare_lengths_by_components({1.5, 0}, {0, 0x1.8p-150}, {0, 0x1.8p-151}, {1.5, 0}), 1);
  expect_compare({1.5, 0}, {0, 0x1.8p-150}, {0, 0x1.8p-151}, {1.5, 0}, 1);
  EXPECT_EQ(compare_lengths_by_components({0, 0}, {3, 4}, {0, 0}, {4, -3}), 0);   // the larger against the larger
  EXPECT_EQ(compare_lengths_by_components({0, 0}, {1, 1}, {0, 0}, {2, 1}), -1);   // the smaller ones tie
  EXPECT_EQ(compare_lengths_by_components({0, 0}, {1, 3}, {0, 0}, {1, 2}), 1);    // the larger decide
  EXPECT_EQ(compare_lengths_by_components({0, 0}, {3, 4}, {0, 0}, {5, 0}), 2);    // 5 > 4 but 0 < 3
  EXPECT_EQ(compare_lengths_by_components({1, 0}, {-0x1p-60, 0}, {0, 0}, {1, 0}), 2);  // a difference rounded
  EXPECT_EQ(compare_lengths_by_components({0, 0}, {1, 0}, {-1e308, 0}, {1e308, 0}), 2);  // an overflow
  std::mt19937_64 rng(29);
  std::uniform_int_distribution<int> scale(-1074, 40), pick(0, 5);
  std::uniform_real_distribution<double> unit(1, 2);
  const double shared[3] = {1.5, 0x1.8p-150, 3.0};
  auto coordinate = [&]() {
    const int k = pick(rng);  // a shared value (ties), zero, or a value of any scale and sign
    if (k < 3) return shared[k];
    if (k == 3) return 0.0;
    return (k == 4 ? 1 : -1) * std::ldexp(unit(rng), scale(rng));
  };
  int decided = 0;
  for (int trial = 0; trial < 50000; ++trial) {
    const Point a{coordinate(), coordinate()}, b{coordinate(), coordinate()}, c{coordinate(), coordinate()},
        d{coordinate(), coordinate()};
    if (const int s = compare_lengths_by_components(a, b, c, d); s != 2) {
      ++decided;
      ASSERT_EQ(s, oracle_compare(a, b, c, d)) << "trial " << trial;
    }
  }
  EXPECT_GT(decided, 1000) << decided;
}

}  // namespace

namespace {
// Below the filter's range the differences are scaled by one power of two and
// filtered again (compare_tiny_squared_lengths). Subnormal lengths whose squares
// need about 90 bits, one exact unit apart in the ordering that double arithmetic
// gets the wrong way round (found by a search against exact integers): the
// scaled filter must not trust its doubles there.
TEST(ReferenceDoubleLengths, SubnormalNearTiesTheDoublesOrderWronglyAfterScaling) {
  struct Case { std::int64_t x1, y1, x2, y2; int expected; };
  const Case cases[] = {{27880308964011, 23955011059611, 27880308997161, 23955011021029, -1},
                        {25733948278172, 20553982645021, 25733948700448, 20553982116324, -1},
                        {26376178162197, 22233335604531, 26376178720021, 22233334942765, -1}};
  const Point o{0, 0};
  for (const Case& k : cases) {
    const Point a{std::ldexp(static_cast<double>(k.x1), -1074), std::ldexp(static_cast<double>(k.y1), -1074)};
    const Point c{std::ldexp(static_cast<double>(k.x2), -1074), std::ldexp(static_cast<double>(k.y2), -1074)};
    // The doubles, scaled to the integers, say the opposite.
    const double x1 = static_cast<double>(k.x1), y1 = static_cast<double>(k.y1);
    const double x2 = static_cast<double>(k.x2), y2 = static_cast<double>(k.y2);
    ASSERT_EQ((x1 * x1 + y1 * y1) - (x2 * x2 + y2 * y2) > 0, k.expected < 0) << "not a case the doubles get wrong";
    expect_compare(a, o, c, o, k.expected);
  }
}
}  // namespace
