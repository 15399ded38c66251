// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind lepp/angle_args.h: an angle of the statistics (lepp/stats.h) as the
// two arguments it gives atan2, and the order of two such angles decided without atan2.
#include "lepp/angle_args.h"

#include "angle_args_inline.h"

#include <algorithm>
#include <cmath>

namespace lepp {
namespace {

using detail::args_of;
using detail::negated;
using detail::scaled_direction;

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

AngleArgs corner_angle_args(const Point& a, const Point& b, const Point& c, int k) { return detail::corner_args(a, b, c, k); }

double signed_degrees(const AngleArgs& a) { return detail::degrees_of(a); }

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
