// SPDX-License-Identifier: GPL-3.0-or-later
// The predicates' exact path (exact_fallback.cpp) first tries doubles: the
// polynomial evaluated step by step, each step checked exact (a sum or
// difference by Knuth's TwoSum, a product by fma's error term), so that the
// sign of the last double is the exact sign. Where the filter fails on grid
// inputs and their midpoints (lengths that tie, cocircular points), every step
// usually is exact, and CGAL::Mpzf (allocations, GMP) is not needed; the first
// inexact step hands the case to Mpzf.
//
// Ranges: a product's error term is a double when both factors are 0 or lie in
// [2^-480, 2^480] (their product's last bit is at least 2^-1064, above the
// smallest subnormal; no overflow); TwoSum's error term is exact unless the sum
// overflows, and an overflow leaves NaN in the check, which fails it.
#pragma once
#include <cmath>
#include <cstddef>
#include <utility>

#include "lepp/pslg.h"

namespace lepp::fast::detail {

// Knuth's TwoSum: the rounded sum, and in err what it lost (x + y = sum + err exactly,
// unless the sum overflows: then err is NaN).
inline double two_sum(double x, double y, double& err) {
  const double s = x + y, yy = s - x;
  err = (x - (s - yy)) + (y - yy);
  return s;
}

class ExactDoubles {
 public:
  double add(double x, double y) {
    double err;
    const double s = two_sum(x, y, err);
    exact_ = exact_ && err == 0;
    return s;
  }
  double sub(double x, double y) { return add(x, -y); }
  double mul(double x, double y) {
    const double p = x * y;
    exact_ = exact_ && fits(x) && fits(y) && std::fma(x, y, -p) == 0;
    return p;
  }
  bool exact() const { return exact_; }
  // The sign of v, a value this evaluation computed: -1, 0, +1, or 2 if a step was inexact.
  int sign(double v) const { return exact_ ? (v > 0) - (v < 0) : 2; }
  // A factor whose products' error terms are doubles (the range above).
  static bool fits(double v) {
    const double m = std::fabs(v);
    return m == 0 || (m >= 0x1p-480 && m <= 0x1p480);
  }

 private:
  bool exact_ = true;
};

// The predicates of predicates.h in doubles: their exact sign, or 2 if a step was inexact.
inline int orient_in_doubles(const Point& a, const Point& b, const Point& c) {
  ExactDoubles e;
  const double bax = e.sub(b.x, a.x), bay = e.sub(b.y, a.y), cax = e.sub(c.x, a.x), cay = e.sub(c.y, a.y);
  return e.sign(e.sub(e.mul(bax, cay), e.mul(bay, cax)));
}

inline int incircle_in_doubles(const Point& a, const Point& b, const Point& c, const Point& d) {
  ExactDoubles e;
  const double adx = e.sub(a.x, d.x), ady = e.sub(a.y, d.y), bdx = e.sub(b.x, d.x), bdy = e.sub(b.y, d.y);
  const double cdx = e.sub(c.x, d.x), cdy = e.sub(c.y, d.y);
  const double alift = e.add(e.mul(adx, adx), e.mul(ady, ady)), blift = e.add(e.mul(bdx, bdx), e.mul(bdy, bdy));
  const double clift = e.add(e.mul(cdx, cdx), e.mul(cdy, cdy));
  const double bc = e.sub(e.mul(bdx, cdy), e.mul(cdx, bdy)), ca = e.sub(e.mul(cdx, ady), e.mul(adx, cdy));
  const double ab = e.sub(e.mul(adx, bdy), e.mul(bdx, ady));
  return e.sign(e.add(e.add(e.mul(alift, bc), e.mul(blift, ca)), e.mul(clift, ab)));
}

inline double squared_length(ExactDoubles& e, const Point& a, const Point& b) {
  const double dx = e.sub(b.x, a.x), dy = e.sub(b.y, a.y);
  return e.add(e.mul(dx, dx), e.mul(dy, dy));
}

inline int compare_sqlen_in_doubles(const Point& a, const Point& b, const Point& c, const Point& d) {
  ExactDoubles e;
  return e.sign(e.sub(squared_length(e, a, b), squared_length(e, c, d)));
}

// |ab|^2 - |cd|^2 without a product: with every difference exact, each pair of components
// sorted by size, (p^2 - r^2) + (q^2 - s^2) has the sign both comparisons agree on (p
// against r, q against s), or that of one where the other ties. Near-ties across scales
// (1.5 and 2^-150 against 1.5 and 2^-151: the ulp clusters of the fuzzers) need 2^300 in
// a product's range and went to Mpzf; here they are two comparisons. 2: undecided (the
// comparisons disagree, or a difference was inexact).
inline int compare_sqlen_by_dominance(const Point& a, const Point& b, const Point& c, const Point& d) {
  ExactDoubles e;
  double p = std::fabs(e.sub(b.x, a.x)), q = std::fabs(e.sub(b.y, a.y));
  double r = std::fabs(e.sub(d.x, c.x)), s = std::fabs(e.sub(d.y, c.y));
  if (!e.exact()) return 2;
  if (p < q) std::swap(p, q);
  if (r < s) std::swap(r, s);
  const int larger = (p > r) - (p < r), smaller = (q > s) - (q < s);
  if (larger == smaller || smaller == 0) return larger;
  return larger == 0 ? smaller : 2;
}

// The exact sign of a sum of doubles, as a nonoverlapping expansion (Shewchuk's
// Grow-Expansion with zero elimination, from "Adaptive Precision Floating-Point
// Arithmetic and Fast Robust Geometric Predicates", 1997): components of increasing
// size, so the sign is the last one's. TwoSum is exact in gradual underflow too; no
// input here comes near overflow (callers' ranges).
template <std::size_t N>
class ExactSum {
 public:
  void add(double b) {
    std::size_t m = 0;
    double q = b;
    for (std::size_t i = 0; i < n_; ++i) {
      double err;
      q = two_sum(q, e_[i], err);
      if (err != 0) e_[m++] = err;
    }
    if (q != 0) e_[m++] = q;
    n_ = m;
  }
  int sign() const { return n_ == 0 ? 0 : (e_[n_ - 1] > 0) - (e_[n_ - 1] < 0); }
  double largest() const { return n_ == 0 ? 0 : e_[n_ - 1]; }
  // The sum of the other components' magnitudes, rounded (at most N - 2 additions): how far
  // the sum may lie from largest(). (Nonoverlapping alone allows {-0.75, 1}: far from 1.)
  double below_largest() const {
    double m = 0;
    for (std::size_t i = 0; i + 1 < n_; ++i) m += std::fabs(e_[i]);
    return m;
  }

 private:
  double e_[N];  // e_[0, n_) only: not zeroed, each call pays for what it uses
  std::size_t n_ = 0;
};

// |ab|^2 - |cd|^2 as an exact sum: each difference h + l by TwoSum, each square
// h^2 + 2hl + l^2 by fma's error terms, every factor 0 or in [2^-480, 2^480] (above:
// ExactDoubles' range, so that each error term is a double). Differences rounded, and
// near-ties across scales that no single double holds (1.5 and 1.125 - 2^-160), are
// decided without Mpzf. 2: a factor out of that range.
inline int compare_sqlen_by_expansion(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double diff[4][2] = {{b.x, a.x}, {b.y, a.y}, {d.x, c.x}, {d.y, c.y}};
  ExactSum<24> sum;  // 4 differences, 6 terms each: each term adds at most one component
  for (int i = 0; i < 4; ++i) {
    double l;
    const double h = two_sum(diff[i][0], -diff[i][1], l);
    if (!ExactDoubles::fits(h) || !ExactDoubles::fits(l)) return 2;
    const double sign = i < 2 ? 1 : -1;
    const double hh = h * h, hl = h * l, ll = l * l;
    for (const double term : {hh, std::fma(h, h, -hh), 2 * hl, 2 * std::fma(h, l, -hl), ll, std::fma(l, l, -ll)})
      if (term != 0) sum.add(sign * term);
  }
  return sum.sign();
}

// (b - a) x (c - a) as an exact sum plus a bounded rest: each difference h + l by TwoSum,
// each of the eight partial products of two factors in ExactDoubles' range added exactly
// (p + its fma error), the others only bounded. The sign is the sum's where the sum's
// largest component clears the bound; else 2. A sliver's orientation against an ulp
// cluster at the origin (the fast engine's sliver clause, fuzz_differential's slowest
// input: 44 % of its time in exact orientations) has differences h = 2, l = 2^-1074:
// no double holds the products, but the parts in range decide.
inline int orient_by_expansion(const Point& a, const Point& b, const Point& c) {
  double d[4][2];  // bax, cay, bay, cax: high part, then what TwoSum lost
  const double ends[4][2] = {{b.x, a.x}, {c.y, a.y}, {b.y, a.y}, {c.x, a.x}};
  for (int i = 0; i < 4; ++i) d[i][0] = two_sum(ends[i][0], -ends[i][1], d[i][1]);
  ExactSum<16> sum;  // two products of two-term factors: 8 partial products, 2 terms each
  double rest = 0;   // at least the sum of |u v| over the partial products left out
  for (int k = 0; k < 2; ++k) {
    const double(&x)[2] = d[2 * k];
    const double(&y)[2] = d[2 * k + 1];
    const double sign = k == 0 ? 1 : -1;
    for (const double u : x)
      for (const double v : y) {
        if (u == 0 || v == 0) continue;
        if (ExactDoubles::fits(u) && ExactDoubles::fits(v)) {
          const double p = u * v;
          sum.add(sign * p);
          if (const double err = std::fma(u, v, -p); err != 0) sum.add(sign * err);
        } else {
          // |u v| rounded (its relative error u) and raised by 2^-50 (a rounding more),
          // plus 2^-1074 for the two roundings' underflow; a NaN or an overflow: no decision.
          rest += std::fabs(u) * std::fabs(v) * (1 + 0x1p-50) + 0x1p-1074;
        }
      }
  }
  if (rest == 0) return sum.sign();
  // The value is top + (the other components) + (the rest), its sign top's where |top|
  // exceeds both bounds. Each bound is a sum of at most 15 positive doubles, within a
  // relative 15 u of its value (sums of subnormals are exact): raised by 2^-40.
  const double top = sum.largest();
  if (std::isfinite(rest) && std::fabs(top) > (sum.below_largest() + rest) * (1 + 0x1p-40)) return (top > 0) - (top < 0);
  return 2;
}

inline int skinny_sign_in_doubles(const Point& apex, const Point& b, const Point& c, double s) {
  ExactDoubles e;
  const double ux = e.sub(b.x, apex.x), uy = e.sub(b.y, apex.y), vx = e.sub(c.x, apex.x), vy = e.sub(c.y, apex.y);
  const double cross = e.sub(e.mul(ux, vy), e.mul(uy, vx));
  const double uu = e.add(e.mul(ux, ux), e.mul(uy, uy)), vv = e.add(e.mul(vx, vx), e.mul(vy, vy));
  return e.sign(e.sub(e.mul(s, e.mul(uu, vv)), e.mul(cross, cross)));
}

inline int area_sign_in_doubles(const Point& a, const Point& b, const Point& c, double twice_area) {
  ExactDoubles e;
  const double bax = e.sub(b.x, a.x), bay = e.sub(b.y, a.y), cax = e.sub(c.x, a.x), cay = e.sub(c.y, a.y);
  const double cross = e.sub(e.mul(bax, cay), e.mul(bay, cax));
  return e.sign(e.sub(std::fabs(cross), twice_area));
}

inline int dot_sign_in_doubles(const Point& v, const Point& a, const Point& b) {
  ExactDoubles e;
  return e.sign(e.add(e.mul(e.sub(a.x, v.x), e.sub(b.x, v.x)), e.mul(e.sub(a.y, v.y), e.sub(b.y, v.y))));
}

inline int sqlen_below_in_doubles(const Point& a, const Point& b, double floor) {
  ExactDoubles e;
  const double l = squared_length(e, a, b);
  return e.sign(e.sub(e.mul(floor, floor), l));
}

// compare_sin2_exact's terms (a, b: three points each): sign(cross_a^2 M_b - cross_b^2 M_a),
// M the largest product of two squared edge lengths.
inline int compare_sin2_in_doubles(const Point* a, const Point* b) {
  ExactDoubles e;
  auto terms = [&e](const Point* t, double& cross2, double& m) {
    const double ux = e.sub(t[1].x, t[0].x), uy = e.sub(t[1].y, t[0].y);
    const double vx = e.sub(t[2].x, t[0].x), vy = e.sub(t[2].y, t[0].y);
    const double cross = e.sub(e.mul(ux, vy), e.mul(uy, vx));
    cross2 = e.mul(cross, cross);
    const double la = squared_length(e, t[0], t[1]), lb = squared_length(e, t[0], t[2]);
    const double lc = squared_length(e, t[1], t[2]);
    m = std::fmax(std::fmax(e.mul(la, lb), e.mul(la, lc)), e.mul(lb, lc));
  };
  double ca, ma, cb, mb;
  terms(a, ca, ma);
  terms(b, cb, mb);
  return e.sign(e.sub(e.mul(ca, mb), e.mul(cb, ma)));
}

}  // namespace lepp::fast::detail
