// SPDX-License-Identifier: GPL-3.0-or-later
// detail::write_double against fmt::format("{}", x), byte for byte, on millions of doubles:
// the .node's coordinates must stay exactly the text they were (issue 40, item 2).
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "double_text.h"

namespace {

double from_bits(std::uint64_t bits) {
  double x;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}

// Compares every value and reports the first few that differ (with their bits, so a
// failure can be replayed).
class Compare {
 public:
  void operator()(double x) {
    char buffer[64];
    const std::string got(buffer, lepp::detail::write_double(buffer, x));
    const std::string want = fmt::format("{}", x);
    ++count_;
    if (got == want) return;
    if (++failures_ <= 10) {
      std::uint64_t bits;
      std::memcpy(&bits, &x, sizeof bits);
      ADD_FAILURE() << fmt::format("bits {:#018x}: write_double gives '{}', fmt gives '{}'", bits, got, want);
    }
  }
  // Both signs of x.
  void both(double x) {
    (*this)(x);
    (*this)(-x);
  }
  // x and its `steps` neighbours on each side, both signs.
  void around(double x, int steps) {
    both(x);
    double up = x, down = x;
    for (int k = 0; k < steps; ++k) {
      up = std::nextafter(up, std::numeric_limits<double>::infinity());
      down = std::nextafter(down, 0.0);
      both(up);
      both(down);
    }
  }
  std::size_t count() const { return count_; }
  ~Compare() { EXPECT_EQ(failures_, 0u) << "of " << count_ << " doubles"; }

 private:
  std::size_t count_ = 0;
  std::size_t failures_ = 0;
};

TEST(DoubleText, SpecialValues) {
  Compare compare;
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (double x : {0.0, 1.0, 0.5, 0.1, 1e-4, 1e-5, 1e15, 1e16, 123456789.0, 9007199254740992.0,
                   std::numeric_limits<double>::max(), std::numeric_limits<double>::min(),
                   std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::epsilon(), inf,
                   std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::signaling_NaN()})
    compare.both(x);
  // Spot checks of the rule itself, so the comparison cannot pass with both sides wrong.
  char buffer[64];
  auto text = [&](double x) { return std::string(buffer, lepp::detail::write_double(buffer, x)); };
  EXPECT_EQ(text(-0.0), "-0");
  EXPECT_EQ(text(1.0), "1");
  EXPECT_EQ(text(-2.5), "-2.5");
  EXPECT_EQ(text(0.0001), "0.0001");
  EXPECT_EQ(text(0.00001), "1e-05");
  EXPECT_EQ(text(1e15), "1000000000000000");
  EXPECT_EQ(text(1e16), "1e+16");
  EXPECT_EQ(text(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(text(-123.456), "-123.456");
}

TEST(DoubleText, PowersOfTenAndTheirNeighbours) {
  Compare compare;
  // Every power of ten a double can come near, from the subnormals to the largest, with
  // 20 neighbours on each side: this covers fmt's switch between fixed and exponent
  // notation (first digit at 1e-5 / 1e-4 and at 1e15 / 1e16) on both sides.
  for (int e = -325; e <= 308; ++e) compare.around(std::pow(10.0, e), 20);
  // The largest values just below the switches, written by their digits.
  for (double x : {9.999999999999999e-5, 0.00009999999999999999, 9999999999999998.0, 999999999999999.9,
                   0.000099999, 0.0001000000000000001})
    compare.around(x, 5);
  // Powers of two too: exact binary fractions, the longest fixed-notation digit strings.
  for (int e = -1074; e <= 1023; ++e) compare.around(std::ldexp(1.0, e), 2);
  EXPECT_GT(compare.count(), 50000u);
}

TEST(DoubleText, RandomBitPatterns) {
  Compare compare;
  std::mt19937_64 random(20261206);
  // Any bits: every exponent, subnormals, infinities, NaN payloads.
  for (int i = 0; i < 1000000; ++i) compare(from_bits(random()));
  // Any significand bits with the exponents that fmt writes in fixed notation (2^-17 to 2^54).
  std::uniform_int_distribution<std::uint64_t> exponent(1023 - 17, 1023 + 54);
  for (int i = 0; i < 1000000; ++i)
    compare(from_bits((random() & 0x800fffffffffffffull) | (exponent(random) << 52)));
  // Subnormals.
  for (int i = 0; i < 100000; ++i) compare(from_bits(random() & 0x800fffffffffffffull));
}

TEST(DoubleText, RandomMeshCoordinates) {
  Compare compare;
  std::mt19937_64 random(40);
  // Magnitudes spread evenly from 1e-3 to 1e4, both signs.
  std::uniform_real_distribution<double> log10_magnitude(-3.0, 4.0);
  for (int i = 0; i < 1000000; ++i) compare.both(std::pow(10.0, log10_magnitude(random)));
  // Square400-like coordinates, and centroids of them (sums of thirds), as the mesher makes.
  std::uniform_real_distribution<double> square(-400.0, 400.0);
  for (int i = 0; i < 500000; ++i) {
    const double a = square(random), b = square(random), c = square(random);
    compare(a);
    compare((a + b + c) / 3.0);
  }
  // Short decimals: integers, halves, and values of a few digits (input vertices).
  for (int i = -100000; i <= 100000; ++i) {
    compare(i);
    compare(i / 2.0);
  }
  std::uniform_int_distribution<std::int64_t> digits(-9999999, 9999999);
  std::uniform_int_distribution<int> scale(0, 9);
  for (int i = 0; i < 300000; ++i) compare(static_cast<double>(digits(random)) / std::pow(10.0, scale(random)));
  // Integers up to 2^53 and beyond (exact, then with trailing zeros from the rounding).
  std::uniform_int_distribution<int> bits(1, 63);
  for (int i = 0; i < 300000; ++i) compare.both(static_cast<double>(random() >> bits(random)));
}

}  // namespace
