// SPDX-License-Identifier: GPL-3.0-or-later
// Private to the reference engine: exact predicates on points whose coordinates
// are doubles (every vertex of the triangulation is). Lazy Epeck builds a node
// per squared distance or product and, where its intervals cannot decide
// (lengths that tie, or squares below the doubles' range: a cluster a few ulps
// wide), an exact Gmpq with gcds: most of the engine's time on such clusters
// (issue 28). Here: a double filter, then the exact value in CGAL::Mpzf (exact
// for +, - and * on doubles, unbounded exponent, no gcd).
//
// Filters: each double value v is within a bound e of the exact one, written
// below (u = 2^-53), on a range where no overflow happens and underflow adds at
// most an absolute error far below the margin; the sign of v is trusted when
// |v| exceeds a margin above e, else the exact path decides.
#pragma once
#include <cmath>

#include "lepp/pslg.h"

namespace lepp::reference::detail {

constexpr double kU = 0x1p-53;

// The exact paths, with no filter (also the filters' oracle in the tests).
// sign(|ab|^2 - |cd|^2).
int compare_squared_lengths_exact(const Point& a, const Point& b, const Point& c, const Point& d);
// sign(sin2 |u|^2 |v|^2 - cross(u, v)^2) with u = b - apex, v = c - apex.
int skinny_sign_exact(const Point& apex, const Point& b, const Point& c, double sin2);

// What s = x + y (rounded) lost: x + y - s exactly (Knuth's TwoSum: its error term is
// exact when nothing overflows; an overflow leaves NaN).
inline double sum_error(double x, double y, double s) {
  const double yy = s - x;
  return (x - (s - yy)) + (y - yy);
}

// x + y == s exactly.
inline bool sum_is_exact(double x, double y, double s) { return sum_error(x, y, s) == 0; }

// Exact without a product: when the four differences are exact doubles, the components
// of each length sorted by size, |ab|^2 - |cd|^2 = (p^2 - r^2) + (q^2 - s^2) has the sign
// the two comparisons agree on, or one's where the other ties; 2 where they disagree or a
// difference was rounded. Ulp clusters compare 1.5 and 2^-150 against 1.5 and 2^-151,
// which no double product resolves (fuzz_differential's slowest inputs spent a third of
// their time in Mpzf on them).
inline int compare_lengths_by_components(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double abx = a.x - b.x, aby = a.y - b.y, cdx = c.x - d.x, cdy = c.y - d.y;
  if (!sum_is_exact(a.x, -b.x, abx) || !sum_is_exact(a.y, -b.y, aby) || !sum_is_exact(c.x, -d.x, cdx) ||
      !sum_is_exact(c.y, -d.y, cdy))
    return 2;  // an overflow leaves NaN in the check, which fails it
  const double p = std::fmax(std::fabs(abx), std::fabs(aby)), q = std::fmin(std::fabs(abx), std::fabs(aby));
  const double r = std::fmax(std::fabs(cdx), std::fabs(cdy)), t = std::fmin(std::fabs(cdx), std::fabs(cdy));
  const int larger = (p > r) - (p < r), smaller = (q > t) - (q < t);
  if (smaller == 0) return larger;
  if (larger == 0 || larger == smaller) return smaller;
  return 2;
}

// Lengths below the filter's range (a cluster of subnormals, fuzz_engine's seeds
// at the limit): a difference of doubles is within u of the exact one (exact when
// it is subnormal), and scaling all four by one power of two is exact and keeps
// the sign, so the same filter runs with the largest at [1, 2); then the exact path.
inline int compare_tiny_squared_lengths(double abx, double aby, double cdx, double cdy, const Point& a, const Point& b,
                                        const Point& c, const Point& d) {
  const double m = std::fmax(std::fmax(std::fabs(abx), std::fabs(aby)), std::fmax(std::fabs(cdx), std::fabs(cdy)));
  if (m > 0 && std::isfinite(m)) {
    const int k = -std::ilogb(m);
    abx = std::ldexp(abx, k), aby = std::ldexp(aby, k), cdx = std::ldexp(cdx, k), cdy = std::ldexp(cdy, k);
    const double lab = abx * abx + aby * aby, lcd = cdx * cdx + cdy * cdy;
    // The larger is at least 1: the underflows (2^-1075 each) are far below the margin.
    const double scaled_margin = 8 * kU * (lab + lcd);
    if (lab - lcd > scaled_margin) return 1;
    if (lcd - lab > scaled_margin) return -1;
  }
  if (const int s = compare_lengths_by_components(a, b, c, d); s != 2) return s;
  return compare_squared_lengths_exact(a, b, c, d);
}

// A squared length computed in doubles, when every step was exact: the differences (TwoSum),
// the squares (fma gives the product's error; it is a double when the square lies in
// [2^-960, 2^960], which |difference| in [2^-480, 2^480] or 0 ensures) and their sum.
// Lengths that tie exactly (grid inputs: most of the filter's failures) need no Mpzf then.
inline bool exact_squared_length(const Point& a, const Point& b, double& out) {
  const double dx = a.x - b.x, dy = a.y - b.y;
  auto fits = [](double v) {
    const double m = std::fabs(v);
    return m == 0 || (m >= 0x1p-480 && m <= 0x1p480);
  };
  if (!fits(dx) || !fits(dy) || !sum_is_exact(a.x, -b.x, dx) || !sum_is_exact(a.y, -b.y, dy)) return false;
  const double xx = dx * dx, yy = dy * dy;
  if (std::fma(dx, dx, -xx) != 0 || std::fma(dy, dy, -yy) != 0) return false;
  out = xx + yy;
  return sum_is_exact(xx, yy, out);
}

// The filter could not decide: both lengths exact in doubles, or the exact path.
inline int compare_undecided_squared_lengths(const Point& a, const Point& b, const Point& c, const Point& d) {
  double lab, lcd;
  if (exact_squared_length(a, b, lab) && exact_squared_length(c, d, lcd)) return (lab > lcd) - (lab < lcd);
  if (const int s = compare_lengths_by_components(a, b, c, d); s != 2) return s;
  return compare_squared_lengths_exact(a, b, c, d);
}

// sign(|ab|^2 - |cd|^2) exactly: -1, 0 or +1.
inline int compare_squared_lengths(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double abx = a.x - b.x, aby = a.y - b.y, cdx = c.x - d.x, cdy = c.y - d.y;
  const double lab = abx * abx + aby * aby, lcd = cdx * cdx + cdy * cdy;
  // Each computed length is within 4.01u of its exact value (one rounded
  // difference, one square, one sum), plus at most three underflows of 2^-1075
  // each. Trusted where the larger is between 2^-900 and 2^1000: no overflow,
  // and the underflows far below the margin of 8u (lab + lcd).
  const double big = std::fmax(lab, lcd);
  if (big >= 0x1p-900 && big <= 0x1p1000) {
    const double margin = 8 * kU * (lab + lcd);
    if (lab - lcd > margin) return 1;
    if (lcd - lab > margin) return -1;
    return compare_undecided_squared_lengths(a, b, c, d);
  }
  if (big < 0x1p-900) return compare_tiny_squared_lengths(abx, aby, cdx, cdy, a, b, c, d);
  return compare_squared_lengths_exact(a, b, c, d);
}

// The angle at apex between u = b - apex and v = c - apex has sin^2 below sin2
// (ALGORITHM.md section 4): cross(u, v)^2 < sin2 |u|^2 |v|^2, exactly. sin2 >= 0.
inline bool skinny_at(const Point& apex, const Point& b, const Point& c, double sin2) {
  const double ux = b.x - apex.x, uy = b.y - apex.y, vx = c.x - apex.x, vy = c.y - apex.y;
  const double uu = ux * ux + uy * uy, vv = vx * vx + vy * vy;
  // With P = |ux vy| + |uy vx|: cross is within 4.02u P, cross^2 within 9.2u P^2,
  // sin2 uu vv within 10.01u of its value, their difference rounded once: all
  // within 12u (rhs + P^2). Underflows: at most 2^-1001 in all where uu and vv
  // lie in [2^-400, 2^400] (and no overflow there).
  if (uu >= 0x1p-400 && uu <= 0x1p400 && vv >= 0x1p-400 && vv <= 0x1p400) {
    const double c1 = ux * vy, c2 = uy * vx, cross = c1 - c2, p = std::fabs(c1) + std::fabs(c2);
    const double rhs = sin2 * (uu * vv), lhs = cross * cross;
    const double margin = 16 * kU * (rhs + p * p) + 0x1p-1000;
    if (rhs - lhs > margin) return true;
    if (lhs - rhs > margin) return false;
  }
  return skinny_sign_exact(apex, b, c, sin2) > 0;
}

}  // namespace lepp::reference::detail
