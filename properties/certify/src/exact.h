// SPDX-License-Identifier: GPL-3.0-or-later
// Exact signs of small polynomials in double coordinates: an interval filter,
// then exact arithmetic (CGAL::Mpzf: exact +, -, * on doubles, no expression
// templates) when the interval straddles zero. Private to the certifier.
#pragma once
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mpzf.h>
#include <CGAL/Interval_nt.h>

#include <array>
#include <cmath>

#include "lepp/pslg.h"

namespace lepp::certify::exact {

// A double with a bound on its distance from the exact value of the expression that
// computed it (round to nearest): the first, cheapest filter of sign(). Each +, - adds
// half an ulp of the result; each * the propagated errors and half an ulp, plus the
// largest error of a product below the normal range (2^-1075, taken as 2^-1072 to cover
// the bound's own products there). The bound's own roundings are covered by widening it
// by 2^-40 relative before it is used. Overflow gives inf or NaN: no decision.
struct ErrorBounded {
  double v = 0;
  double e = 0;  // |exact - v| <= e (up to the widening above)
  ErrorBounded() = default;
  explicit ErrorBounded(double x) : v(x) {}
  ErrorBounded(double x, double err) : v(x), e(err) {}
  static constexpr double kHalfUlp = 0x1p-53;
  static constexpr double kTiny = 0x1p-1072;
  friend ErrorBounded operator+(const ErrorBounded& a, const ErrorBounded& b) {
    const double r = a.v + b.v;
    return {r, a.e + b.e + kHalfUlp * std::abs(r)};
  }
  friend ErrorBounded operator-(const ErrorBounded& a, const ErrorBounded& b) {
    const double r = a.v - b.v;
    return {r, a.e + b.e + kHalfUlp * std::abs(r)};
  }
  friend ErrorBounded operator*(const ErrorBounded& a, const ErrorBounded& b) {
    const double r = a.v * b.v;
    return {r, std::abs(a.v) * b.e + std::abs(b.v) * a.e + a.e * b.e + kHalfUlp * std::abs(r) + kTiny};
  }
  // The sign of the exact value if the bound decides it, else 2.
  int sign_or_undecided() const {
    const double bound = e * (1 + 0x1p-40) + kTiny;
    if (!(std::isfinite(v) && std::isfinite(bound))) return 2;
    if (v > bound) return 1;
    if (v < -bound) return -1;
    if (v == 0 && e == 0) return 0;  // every step exact (differences of equal doubles, sums of zeros)
    return 2;
  }
};

}  // namespace lepp::certify::exact

// CGAL::abs for ErrorBounded, as the predicates write it (a plain overload: CGAL's own
// template would take the type's traits).
namespace CGAL {
inline lepp::certify::exact::ErrorBounded abs(const lepp::certify::exact::ErrorBounded& a) { return {std::abs(a.v), a.e}; }
}  // namespace CGAL

namespace lepp::certify::exact {

// f is a generic callable taking a number-type tag (a value of type NT) and
// returning an NT: evaluated with a rounding-error bound first (ErrorBounded),
// then on intervals, exactly only if both leave the sign open. The
// polynomials use only +, -, * and abs, which Mpzf computes exactly. (Boost's
// expression-template rationals were used here before; g++ -O3 turned a path
// through them into a null dereference, caught by fuzz_support_test.)
template <class F>
int sign(const F& f) {
  if (const int s = f(ErrorBounded(0)).sign_or_undecided(); s != 2) return s;
  {
    CGAL::Protect_FPU_rounding<true> guard;
    const CGAL::Interval_nt<false> r = f(CGAL::Interval_nt<false>(0));
    if (r.inf() > 0) return 1;
    if (r.sup() < 0) return -1;
    if (r.inf() == 0 && r.sup() == 0) return 0;
  }
  return static_cast<int>(CGAL::sign(f(CGAL::Mpzf(0))));
}

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
inline K::Point_2 cg(const Point& p) { return {p.x, p.y}; }

// orientation(a, b, c): +1 counter-clockwise, 0 collinear, -1 clockwise (filtered, exact).
inline int orient(const Point& a, const Point& b, const Point& c) {
  return static_cast<int>(CGAL::orientation(cg(a), cg(b), cg(c)));
}

// +1 iff d lies strictly inside the circle through the CCW triangle abc.
inline int incircle(const Point& a, const Point& b, const Point& c, const Point& d) {
  return static_cast<int>(CGAL::side_of_oriented_circle(cg(a), cg(b), cg(c), cg(d)));
}

// sign(|ab|^2 - |cd|^2)
inline int compare_squared_length(const Point& a, const Point& b, const Point& c, const Point& d) {
  return sign([&](auto z) -> decltype(z) {
    using NT = decltype(z);
    NT ux = NT(b.x) - NT(a.x), uy = NT(b.y) - NT(a.y), vx = NT(d.x) - NT(c.x), vy = NT(d.y) - NT(c.y);
    return (ux * ux + uy * uy) - (vx * vx + vy * vy);
  });
}

// sign(dot(p - o, q - o))
inline int sign_dot(const Point& o, const Point& p, const Point& q) {
  return sign([&](auto z) -> decltype(z) {
    using NT = decltype(z);
    return (NT(p.x) - NT(o.x)) * (NT(q.x) - NT(o.x)) + (NT(p.y) - NT(o.y)) * (NT(q.y) - NT(o.y));
  });
}

// The two sides of the angle at o, toward p and q, with their error bounds: the first
// filter of the angle predicates below, shared by their two signs.
struct Sides {
  ErrorBounded ux, uy, vx, vy;
  Sides(const Point& o, const Point& p, const Point& q)
      : ux(ErrorBounded(p.x) - ErrorBounded(o.x)),
        uy(ErrorBounded(p.y) - ErrorBounded(o.y)),
        vx(ErrorBounded(q.x) - ErrorBounded(o.x)),
        vy(ErrorBounded(q.y) - ErrorBounded(o.y)) {}
  int dot_sign() const { return (ux * vx + uy * vy).sign_or_undecided(); }  // sign_dot(o, p, q), or 2
};

// The angle at c of triangle (c, a, b) is > 120 degrees:
// dot(ca, cb) < 0 and 4 dot^2 > |ca|^2 |cb|^2.
inline bool angle_over_120(const Point& c, const Point& a, const Point& b) {
  {  // both signs through the first filter at once; any sign it leaves open: the full path below
    const Sides z(c, a, b);
    const int d = z.dot_sign();
    if (d == 0 || d == 1) return false;
    if (d == -1) {
      const ErrorBounded dot = z.ux * z.vx + z.uy * z.vy;
      const int s = (ErrorBounded(4) * dot * dot - (z.ux * z.ux + z.uy * z.uy) * (z.vx * z.vx + z.vy * z.vy)).sign_or_undecided();
      if (s != 2) return s > 0;
    }
  }
  if (sign_dot(c, a, b) >= 0) return false;
  return sign([&](auto z) -> decltype(z) {
           using NT = decltype(z);
           NT ux = NT(a.x) - NT(c.x), uy = NT(a.y) - NT(c.y), vx = NT(b.x) - NT(c.x), vy = NT(b.y) - NT(c.y);
           NT dot = ux * vx + uy * vy;
           return NT(4) * dot * dot - (ux * ux + uy * uy) * (vx * vx + vy * vy);
         }) > 0;
}

// The angle at o between p and q is acute and its sin^2 is below s:
// dot > 0 and cross^2 < s |op|^2 |oq|^2, exactly (s is a double, taken as the rational it is).
inline bool acute_angle_sin2_below(const Point& o, const Point& p, const Point& q, double s) {
  {  // as angle_over_120
    const Sides z(o, p, q);
    const int d = z.dot_sign();
    if (d == 0 || d == -1) return false;
    if (d == 1) {
      const ErrorBounded cross = z.ux * z.vy - z.uy * z.vx;
      const int c = (cross * cross - ErrorBounded(s) * (z.ux * z.ux + z.uy * z.uy) * (z.vx * z.vx + z.vy * z.vy)).sign_or_undecided();
      if (c != 2) return c < 0;
    }
  }
  if (sign_dot(o, p, q) <= 0) return false;
  return sign([&](auto z) -> decltype(z) {
           using NT = decltype(z);
           NT ux = NT(p.x) - NT(o.x), uy = NT(p.y) - NT(o.y), vx = NT(q.x) - NT(o.x), vy = NT(q.y) - NT(o.y);
           NT cross = ux * vy - uy * vx;
           return cross * cross - NT(s) * (ux * ux + uy * uy) * (vx * vx + vy * vy);
         }) < 0;
}

// One triangle (x0, x1, x2) through one first filter: its sides' squared lengths and its
// cross product (twice the area, the same at every corner) with their error bounds, once,
// for the signs the index's pass over triangles needs (longest side, small corners, area
// bound). Each sign the filter leaves open takes the full path of the predicate it
// stands for: the same answers, in fewer operations and one load of the points.
class TriangleShape {
 public:
  TriangleShape(const Point& x0, const Point& x1, const Point& x2) : x_{&x0, &x1, &x2} {
    for (int i = 0; i < 3; ++i) {  // side i runs x[i] -> x[i + 1]
      const Point &a = *x_[i], &b = *x_[(i + 1) % 3];
      side_[i][0] = ErrorBounded(b.x) - ErrorBounded(a.x);
      side_[i][1] = ErrorBounded(b.y) - ErrorBounded(a.y);
      length2_[i] = side_[i][0] * side_[i][0] + side_[i][1] * side_[i][1];
    }
    cross_ = side_[0][0] * side_[2][1] - side_[0][1] * side_[2][0];
    cross2_ = cross_ * cross_;
  }
  // angle_over_120 at corner i (between sides i and i + 2, toward x[i + 1] and x[i + 2]):
  // dot < 0 and 4 dot^2 > |u|^2 |v|^2, the dot product of side i and side i + 2 reversed.
  // Any triangle.
  bool angle_over_120_at(int i) const {
    const int j = (i + 2) % 3;
    const ErrorBounded minus_dot = side_[i][0] * side_[j][0] + side_[i][1] * side_[j][1];  // -dot(u, v)
    const int d = minus_dot.sign_or_undecided();
    if (d == 0 || d == -1) return false;  // dot >= 0: not obtuse
    if (d == 1) {
      const int s = (ErrorBounded(4) * minus_dot * minus_dot - length2_[i] * length2_[j]).sign_or_undecided();
      if (s != 2) return s > 0;
    }
    return angle_over_120(*x_[i], *x_[(i + 1) % 3], *x_[(i + 2) % 3]);
  }
  // |orient(x0, x1, x2)| > 2 * bound, exactly (the area above a bound): from the same
  // cross product, then the full exact path if its filter leaves the sign open. Any triangle.
  bool doubled_area_above(double bound) const {
    const int s = (CGAL::abs(cross_) - (ErrorBounded(bound) + ErrorBounded(bound))).sign_or_undecided();
    if (s != 2) return s > 0;
    return sign([&](auto z) -> decltype(z) {
             using NT = decltype(z);
             const Point &a = *x_[0], &b = *x_[1], &c = *x_[2];
             NT det = (NT(b.x) - NT(a.x)) * (NT(c.y) - NT(a.y)) - (NT(b.y) - NT(a.y)) * (NT(c.x) - NT(a.x));
             return CGAL::abs(det) - (NT(bound) + NT(bound));
           }) > 0;
  }
  // Side i's squared length (x[i] to x[i + 1]), as compare_squared_length's first filter computes it.
  const std::array<ErrorBounded, 3>& squared_lengths() const { return length2_; }
  // acute_angle_sin2_below at corner i (between sides i and i + 2). Only for a triangle
  // that is not degenerate (orient != 0) and a corner i that does not face a longest side
  // (for longest side L, corner L + 2 mod 3): it faces a side no longer than another, so
  // its angle is below 90 degrees and its dot product positive, and the predicate
  // reduces to cross^2 < s |u|^2 |v|^2.
  bool sin2_below(int i, double s) const {
    const int c = (cross2_ - ErrorBounded(s) * length2_[i] * length2_[(i + 2) % 3]).sign_or_undecided();
    if (c != 2) return c < 0;
    return acute_angle_sin2_below(*x_[i], *x_[(i + 1) % 3], *x_[(i + 2) % 3], s);
  }

 private:
  const Point* x_[3];
  ErrorBounded side_[3][2];
  std::array<ErrorBounded, 3> length2_;
  ErrorBounded cross_, cross2_;
};

}  // namespace lepp::certify::exact
