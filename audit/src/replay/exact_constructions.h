// SPDX-License-Identifier: GPL-3.0-or-later
// Private to the conformance replay: the exact constructions of the replay
// and of its deviation catalogue that can divide by zero or meet a value
// beyond the doubles, each with a defined answer on degenerate input instead
// of a signal. GMP raises SIGFPE on a division by zero and on an infinity or
// a NaN made into a rational (issue 30: `lepp audit` died on a program's
// output whose replay held a flat triangle), and a signal cannot be caught.
#pragma once
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <utility>

#include "triangulation.h"  // reference/src: the exact engine's CGAL types

namespace lepp::audit::replay_detail {

using namespace lepp::reference::detail;

// The circumcenter of abc, exactly; none when the three points are collinear
// (repeated points included): no circle passes through them, and CGAL's
// construction would divide by zero.
inline std::optional<CPoint> guarded_circumcenter(const CPoint& a, const CPoint& b, const CPoint& c) {
  if (CGAL::collinear(a, b, c)) return std::nullopt;
  return CGAL::circumcenter(a, b, c);
}

// The area centroid (centre of mass) of the quad made of triangles abc and abd
// on both sides of ab: their centroids weighted by their areas, exactly. None
// when both triangles are flat: no area, no centre of mass (and the division
// by the total area would be by zero).
inline std::optional<CPoint> guarded_area_centroid(const CPoint& a, const CPoint& b, const CPoint& c, const CPoint& d) {
  FT w1 = CGAL::abs((b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x()));
  FT w2 = CGAL::abs((b.x() - a.x()) * (d.y() - a.y()) - (b.y() - a.y()) * (d.x() - a.x()));
  FT w = 3 * (w1 + w2);
  // sign, not CGAL::is_zero: the latter is Lazy_exact_nt's algebraic is_zero, which
  // evaluates w exactly every time (GMP on the whole expression); sign reads the
  // interval first and goes exact only when it straddles 0.
  if (CGAL::sign(w) == CGAL::ZERO) return std::nullopt;
  return CPoint((w1 * (a.x() + b.x() + c.x()) + w2 * (a.x() + b.x() + d.x())) / w,
                (w1 * (a.y() + b.y() + c.y()) + w2 * (a.y() + b.y() + d.y())) / w);
}

// Of two adjacent doubles, the one whose significand is even: round to nearest's
// answer on a tie between them.
inline double even_of(double a, double b) {
  std::int64_t bits;
  std::memcpy(&bits, &a, sizeof bits);
  return (bits & 1) ? b : a;
}

// The double nearest to x (ties to even), from the exact value. Beyond the
// largest double (a circumcenter far off a nearly flat triangle) round to
// nearest gives an infinity from DBL_MAX plus half its ulp on (a tie goes to
// the even side, the infinity), else DBL_MAX; FT(infinity) is never made.
inline double round_nearest(const FT& x) {
  // A value whose interval approximation is one double is that double: no exact
  // evaluation (a midpoint or centroid that rounding did not touch).
  const std::pair<double, double> approx = CGAL::to_interval(x);
  if (approx.first == approx.second) return approx.first;
  std::pair<double, double> iv = CGAL::to_interval(CGAL::exact(x));
  if (iv.first == iv.second) return iv.first;
  if (!std::isfinite(iv.first) || !std::isfinite(iv.second)) {
    const double big = std::isfinite(iv.first) ? iv.first : iv.second;  // +-DBL_MAX
    const FT edge = FT(big) + FT(std::copysign(std::ldexp(1.0, 970), big));
    const bool beyond = big > 0 ? !(x < edge) : !(x > edge);
    return beyond ? std::copysign(std::numeric_limits<double>::infinity(), big) : big;
  }
  double lo = iv.first, hi = std::nextafter(lo, std::numeric_limits<double>::infinity());
  if (hi != iv.second) return CGAL::to_double(x);  // not a tight interval: cannot happen with GMP rationals
  CGAL::Comparison_result r = CGAL::compare(x, (FT(lo) + FT(hi)) / 2);
  if (r == CGAL::SMALLER) return lo;
  if (r == CGAL::LARGER) return hi;
  return even_of(lo, hi);
}

}  // namespace lepp::audit::replay_detail
