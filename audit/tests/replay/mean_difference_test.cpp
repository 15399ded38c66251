// SPDX-License-Identifier: GPL-3.0-or-later
// The replay's distance to a mean of doubles without GMP (audit/src/replay/
// mean_difference.h): the same double as CGAL's to_double of the lazy difference to
// a mean of two, three or four doubles, on random coordinates a few ulps to far from
// the mean, of every sign and many magnitudes; and the tightest interval the same as
// CGAL's of the exact rational.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "../../src/replay/exact_constructions.h"
#include "../../src/replay/mean_difference.h"

namespace {

using lepp::audit::replay_detail::difference_to_double;
using lepp::audit::replay_detail::FT;
using lepp::audit::replay_detail::mean_difference_interval;
using lepp::audit::replay_detail::mean_nearest;
using lepp::audit::replay_detail::round_nearest;

// The coordinate the replay builds for a mean: a midpoint, a triangle's centroid
// (a + b + c) / 3, or ((a + b) + (c + d)) / 4.
FT mean_ft(const double* m, int n) {
  if (n == 2) return (FT(m[0]) + FT(m[1])) / 2;
  if (n == 3) return (FT(m[0]) + FT(m[1]) + FT(m[2])) / 3;
  return ((FT(m[0]) + FT(m[1])) + (FT(m[2]) + FT(m[3]))) / 4;
}

double ulps(double x, std::int64_t k) {
  for (; k > 0; --k) x = std::nextafter(x, INFINITY);
  for (; k < 0; ++k) x = std::nextafter(x, -INFINITY);
  return x;
}

struct Counts {
  int fast = 0, cgal = 0;
  int fast_by_n[5] = {};
};

// One case: the fast path's double against CGAL's, each on its own fresh lazy number
// (CGAL's answer may depend on what was evaluated before: not here).
void check(double v, const double* m, int n, Counts& counts) {
  const double ours = difference_to_double(v, mean_ft(m, n), m, n);
  const double cgal = CGAL::to_double(FT(v) - mean_ft(m, n));
  ASSERT_EQ(ours, cgal) << std::hexfloat << "v " << v << " m " << m[0] << " " << m[1] << " n " << n;
  if (const auto iv = mean_difference_interval(v, m, n)) {
    const std::pair<double, double> exact = CGAL::to_interval(CGAL::exact(FT(v) - mean_ft(m, n)));
    ASSERT_EQ(iv->first, exact.first) << std::hexfloat << "v " << v << " m " << m[0];
    ASSERT_EQ(iv->second, exact.second) << std::hexfloat << "v " << v << " m " << m[0];
    ++counts.fast;
    ++counts.fast_by_n[n];
  } else {
    ++counts.cgal;
  }
}

TEST(MeanDifference, TheSameDoubleAsCGALsToDouble) {
  std::mt19937_64 rng(20261207);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> exponent(-60, 60), spread(0, 40), near(-40, 40), pick(0, 5);
  Counts counts;
  for (int i = 0; i < 60000; ++i) {
    const int n = 2 + i % 3;
    const double base = std::ldexp(unit(rng), exponent(rng));
    double m[4];
    for (int k = 0; k < n; ++k) m[k] = pick(rng) == 0 ? base : base + std::ldexp(unit(rng), exponent(rng) - spread(rng));
    // The program's coordinate: the mean's double a few ulps off, or the mean of
    // other doubles, or far from it, or 0.
    const double mean = CGAL::to_double(mean_ft(m, n));
    double v;
    switch (pick(rng)) {
      case 0: v = mean; break;
      case 1: v = ulps(mean, near(rng)); break;
      case 2: v = ulps(mean, near(rng) * 1000); break;
      case 3: v = mean + std::ldexp(unit(rng), exponent(rng)); break;
      case 4: v = 0; break;
      default: v = ulps(mean, near(rng) % 3); break;
    }
    check(v, m, n, counts);
    if (HasFatalFailure()) return;
  }
  // The fast path answers most of them (else this compares CGAL with itself).
  EXPECT_GT(counts.fast, 15000);
  for (int n : {2, 3, 4}) EXPECT_GT(counts.fast_by_n[n], 4000) << n;
}

// Where the fast path steps aside: subnormal and huge values, and an exact zero.
TEST(MeanDifference, LeavesTinyAndHugeValuesToCGAL) {
  Counts counts;
  const double tiny[2] = {0x1p-1060, 0x1.8p-1060};
  check(0x1p-1060, tiny, 2, counts);
  EXPECT_FALSE(mean_difference_interval(0x1p-1060, tiny, 2));
  const double huge[2] = {0x1p+1020, 0x1.8p+1020};
  check(0x1.4p+1020, huge, 2, counts);
  EXPECT_FALSE(mean_difference_interval(0x1.4p+1020, huge, 2));
  const double one[4] = {1, 2, 3, 4};
  check(2.5, one, 4, counts);  // exactly the mean: 0
  ASSERT_TRUE(mean_difference_interval(2.5, one, 4));
  EXPECT_EQ(*mean_difference_interval(2.5, one, 4), std::make_pair(0.0, 0.0));
  const double third[2] = {0.1, 0.2};  // 0.15000000000000002 and the exact mean differ
  check(0.15, third, 2, counts);
  const double five[5] = {1, 2, 3, 4, 5};
  EXPECT_FALSE(mean_difference_interval(3.0, five, 5));  // not two, three or four
  EXPECT_FALSE(mean_nearest(five, 5));
  // A third is no double: 1/3's two neighbours, and 3 x 0.1's rounding error counted.
  const double thirds[3] = {0, 0, 1};
  ASSERT_TRUE(mean_difference_interval(0.0, thirds, 3));
  EXPECT_EQ(*mean_difference_interval(0.0, thirds, 3), CGAL::to_interval(CGAL::exact(FT(0) - mean_ft(thirds, 3))));
  check(1.0 / 3, thirds, 3, counts);
  const double tenths[3] = {0.1, 0.1, 0.1};
  check(0.1, tenths, 3, counts);
  ASSERT_TRUE(mean_difference_interval(0.1, tenths, 3));
  EXPECT_EQ(*mean_difference_interval(0.1, tenths, 3), std::make_pair(0.0, 0.0));  // exactly 0.1's double
}

// The mean rounded to the nearest double, ties to even: round_nearest's answer.
TEST(MeanDifference, TheNearestDoubleOfAMeanIsRoundNearests) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> exponent(-60, 60), spread(0, 60), pick(0, 3);
  int fast = 0;
  for (int i = 0; i < 60000; ++i) {
    const int n = 2 + i % 3;
    const double base = std::ldexp(unit(rng), exponent(rng));
    double m[4];
    for (int k = 0; k < n; ++k)
      m[k] = pick(rng) == 0 ? ulps(base, k) : base + std::ldexp(unit(rng), exponent(rng) - spread(rng));
    const std::optional<double> ours = mean_nearest(m, n);
    if (!ours) continue;
    ++fast;
    ASSERT_EQ(*ours, round_nearest(mean_ft(m, n))) << std::hexfloat << m[0] << " " << m[1] << " n " << n;
  }
  EXPECT_GT(fast, 45000);
  // Ties: half an ulp above 1 goes down to 1 (even), above 1 + ulp up to 1 + 2 ulp.
  const double one = 1, up = std::nextafter(1.0, 2.0), up2 = std::nextafter(up, 2.0), up3 = std::nextafter(up2, 2.0);
  const double tie_down[2] = {one, up}, tie_up[2] = {up, up2}, exact[2] = {one, up2}, quarter[4] = {one, one, one, up3};
  EXPECT_EQ(mean_nearest(tie_down, 2), one);
  EXPECT_EQ(mean_nearest(tie_up, 2), up2);
  EXPECT_EQ(mean_nearest(exact, 2), up);
  EXPECT_EQ(mean_nearest(quarter, 4), up);  // 1 + 3/4 ulp: nearer 1 + ulp
  EXPECT_EQ(round_nearest((FT(one) + FT(up)) / 2), one);
  const double negative[2] = {-one, -up};
  EXPECT_EQ(mean_nearest(negative, 2), -one);
  const double tiny[2] = {0x1p-1060, 0x1.8p-1060};
  EXPECT_FALSE(mean_nearest(tiny, 2));
}

}  // namespace
