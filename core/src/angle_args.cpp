// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind lepp/angle_args.h: an angle of the statistics (lepp/stats.h) as the
// two arguments it gives atan2, and the order of two such angles decided without atan2.
#include "lepp/angle_args.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace lepp {
namespace {

// 2^k for a k of a normal double (-1022 to 1023), built from its bits.
double power_of_two(int k) {
  const std::uint64_t bits = static_cast<std::uint64_t>(k + 1023) << 52;
  double d;
  std::memcpy(&d, &bits, sizeof d);
  return d;
}

// ilogb(m) for a normal m, read from its bits.
int exponent_of(double m) {
  std::uint64_t bits;
  std::memcpy(&bits, &m, sizeof bits);
  return static_cast<int>((bits >> 52) & 0x7ff) - 1023;
}

// p - o scaled by a power of two so that its larger component is in [1, 2): the
// direction is kept and neither the difference nor the products after it over- or
// underflow. A difference that overflows is taken of the halves (exact at that size).
Point scaled_direction(const Point& o, const Point& p) {
  double dx = p.x - o.x, dy = p.y - o.y;
  if (!std::isfinite(dx) || !std::isfinite(dy)) dx = p.x / 2 - o.x / 2, dy = p.y / 2 - o.y / 2;
  const double m = std::max(std::abs(dx), std::abs(dy));
  if (!(m > 0) || !std::isfinite(m)) return {dx, dy};
  if (m >= 0x1p-1000 && m < 0x1p1000) {
    // A product by an exact power of two is rounded once, as ldexp rounds: the same
    // doubles without the library calls (the statistics make three per triangle).
    const double scale = power_of_two(-exponent_of(m));
    return {dx * scale, dy * scale};
  }
  const int e = std::ilogb(m);
  return {std::ldexp(dx, -e), std::ldexp(dy, -e)};
}

AngleArgs args_of(const Point& u, const Point& v) { return {u.x * v.y - u.y * v.x, u.x * v.x + u.y * v.y}; }

Point negated(const Point& u) { return {-u.x, -u.y}; }

// A scaled direction of a side of positive, finite length: one component in [1, 2).
bool usable(const Point& u) { return std::max(std::abs(u.x), std::abs(u.y)) >= 1 && std::isfinite(u.x) && std::isfinite(u.y); }

}  // namespace

AngleArgs angle_args(const Point& o, const Point& p, const Point& q) {
  return args_of(scaled_direction(o, p), scaled_direction(o, q));
}

std::array<AngleArgs, 3> triangle_angle_args(const Point& a, const Point& b, const Point& c) {
  const Point ab = scaled_direction(a, b), bc = scaled_direction(b, c), ca = scaled_direction(c, a);
  // A zero-length or non-finite side: its reversal is not its negation bit for bit
  // (a zero's sign), and both cross and dot may be zero, where atan2 reads that sign.
  if (!usable(ab) || !usable(bc) || !usable(ca)) return {angle_args(a, b, c), angle_args(b, c, a), angle_args(c, a, b)};
  return {args_of(ab, negated(ca)), args_of(bc, negated(ab)), args_of(ca, negated(bc))};
}

AngleArgs corner_angle_args(const Point& a, const Point& b, const Point& c, int k) {
  // The two sides at corner k, as triangle_angle_args scales them.
  switch (k) {
    case 0: return args_of(scaled_direction(a, b), negated(scaled_direction(c, a)));
    case 1: return args_of(scaled_direction(b, c), negated(scaled_direction(a, b)));
    default: return args_of(scaled_direction(c, a), negated(scaled_direction(b, c)));
  }
}

double signed_degrees(const AngleArgs& a) { return std::atan2(a.cross, a.dot) * 180.0 / M_PI; }

bool clearly_smaller(const AngleArgs& a, const AngleArgs& b) {
  // With y = |cross| and x = dot, an angle is atan2(y, x) in [0, pi], and
  // sin(angle_b - angle_a) r_a r_b = y_b x_a - y_a x_b, where r = hypot(x, y) is at
  // most |x| + y. The scaled directions keep |x| and y below 8 and r at least 1, so
  // the products' rounding (a few 2^-53 of the bound) is far below the 2^-40 asked.
  constexpr double kMargin = 0x1p-40;
  const double ya = std::abs(a.cross), yb = std::abs(b.cross);
  const double bound = (std::abs(a.dot) + ya) * (std::abs(b.dot) + yb);
  return yb * a.dot - ya * b.dot > kMargin * bound;
}

}  // namespace lepp
