// SPDX-License-Identifier: GPL-3.0-or-later
// lepp/rounding.h: the doubles around an exact midpoint or centroid coordinate,
// and the precision floor's quick answer far from the limit (ALGORITHM.md section 8b).
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "lepp/rounding.h"

namespace lepp {
namespace {

std::vector<double> values(const DoublesAround& r) { return {r.begin(), r.end()}; }

TEST(DoublesAround, AnExactMeanIsItself) {
  EXPECT_EQ(values(doubles_around_midpoint(1, 3)), std::vector<double>{2});
  EXPECT_EQ(values(doubles_around_centroid(0, 1, 2, 5)), std::vector<double>{2});
  EXPECT_EQ(values(doubles_around_midpoint(-0.0, 0.0)), std::vector<double>{0});
}

TEST(DoublesAround, AMeanBetweenTwoDoublesGivesBoth) {
  // 1 and 1 + 2^-52: their mean is 1 + 2^-53, between two adjacent doubles.
  const double up = std::nextafter(1.0, 2.0);
  EXPECT_EQ(values(doubles_around_midpoint(1, up)), (std::vector<double>{1, up}));
  // Negative: ascending still, truncation toward zero is the upper one.
  EXPECT_EQ(values(doubles_around_midpoint(-1, -up)), (std::vector<double>{-up, -1}));
  // A centroid whose exact value is a quarter ulp above 2^40: 2^40 and the next double.
  const double big = 0x1p40, next = std::nextafter(big, HUGE_VAL);
  EXPECT_EQ(values(doubles_around_centroid(big, big, big, next)), (std::vector<double>{big, next}));
}

TEST(DoublesAround, SubnormalMeans) {
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(values(doubles_around_midpoint(0, tiny)), (std::vector<double>{0, tiny}));
  EXPECT_EQ(values(doubles_around_midpoint(-tiny, 0)), (std::vector<double>{-tiny, -0.0}));
}

TEST(DoublesAround, BracketsTheFormulaAtRandom) {
  // The exact mean lies between the two (and the correctly rounded sum of two
  // halves, a double, is one of them whenever the sum itself does not round).
  std::mt19937_64 gen(7);
  std::uniform_real_distribution<double> u(-1e6, 1e6);
  for (int i = 0; i < 2000; ++i) {
    const double a = u(gen), b = std::nextafter(a, HUGE_VAL) + (i % 3) * std::ldexp(std::fabs(a), -50);
    const DoublesAround r = doubles_around_midpoint(a, b);
    ASSERT_GE(r.count, 1);
    EXPECT_LE(r.value[0], std::max(a, b));
    EXPECT_GE(r.value[r.count - 1], std::min(a, b));
    if (r.count == 2) EXPECT_EQ(std::nextafter(r.value[0], HUGE_VAL), r.value[1]);
  }
}

// The quick answer far from the limit must agree with the exact rule: at every
// scale, differences around M * 2^-50 (where the quick test switches) and a few ulps.
TEST(PrecisionFloor, QuickAnswerAgreesWithTheExactRule) {
  std::mt19937_64 gen(11);
  for (int e : {-1074, -1060, -1022, -1000, -970, -100, -1, 0, 1, 40, 52, 60, 500, 1000, 1023}) {
    for (int i = 0; i < 200; ++i) {
      const double m = std::ldexp(1.0 + std::uniform_real_distribution<double>(0, 1)(gen), e);
      if (!std::isfinite(m)) continue;
      for (int k : {0, 1, 2, 3, 4, 5, 8}) {
        const double step = std::ldexp(m, -50) * (0.5 + 0.25 * k);
        const Point a{m, m / 3}, b{m - step, m / 3}, c{m, m / 3 + step}, d{m - step / 2, m / 3 - step / 2};
        for (const Point& q : {b, c, d}) EXPECT_EQ(below_precision_floor(a, q), detail::below_precision_floor_exact(a, q)) << m << " " << k;
        Point near{m, m / 3};
        for (int u = 0; u < k; ++u) near.x = std::nextafter(near.x, 0.0);
        EXPECT_EQ(below_precision_floor(a, near), detail::below_precision_floor_exact(a, near));
        if (e > -1000) EXPECT_EQ(below_precision_floor(a, near), k < 4) << m << " " << k;  // k ulps of m apart
      }
    }
  }
}

}  // namespace
}  // namespace lepp
