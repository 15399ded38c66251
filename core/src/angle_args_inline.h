// SPDX-License-Identifier: GPL-3.0-or-later
// The arithmetic of lepp/angle_args.h inline, for the statistics' loop over every
// triangle (stats.cpp): the same expressions, so the same doubles, without a call per
// side (issue 40). Internal to lepp_core.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "lepp/angle_args.h"

namespace lepp::detail {

// 2^k for a k of a normal double (-1022 to 1023), built from its bits.
inline double power_of_two(int k) {
  const std::uint64_t bits = static_cast<std::uint64_t>(k + 1023) << 52;
  double d;
  std::memcpy(&d, &bits, sizeof d);
  return d;
}

// ilogb(m) for a normal m, read from its bits.
inline int exponent_of(double m) {
  std::uint64_t bits;
  std::memcpy(&bits, &m, sizeof bits);
  return static_cast<int>((bits >> 52) & 0x7ff) - 1023;
}

// p - o scaled by a power of two so that its larger component is in [1, 2): the
// direction is kept and neither the difference nor the products after it over- or
// underflow. A difference that overflows is taken of the halves (exact at that size).
inline Point scaled_direction(const Point& o, const Point& p) {
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

inline AngleArgs args_of(const Point& u, const Point& v) { return {u.x * v.y - u.y * v.x, u.x * v.x + u.y * v.y}; }

inline Point negated(const Point& u) { return {-u.x, -u.y}; }

// corner_angle_args (lepp/angle_args.h): the two sides at corner k, as
// triangle_angle_args scales them.
inline AngleArgs corner_args(const Point& a, const Point& b, const Point& c, int k) {
  switch (k) {
    case 0: return args_of(scaled_direction(a, b), negated(scaled_direction(c, a)));
    case 1: return args_of(scaled_direction(b, c), negated(scaled_direction(a, b)));
    default: return args_of(scaled_direction(c, a), negated(scaled_direction(b, c)));
  }
}

// signed_degrees (lepp/angle_args.h).
inline double degrees_of(const AngleArgs& a) { return std::atan2(a.cross, a.dot) * 180.0 / M_PI; }

}  // namespace lepp::detail
