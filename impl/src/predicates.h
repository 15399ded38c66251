// SPDX-License-Identifier: GPL-3.0-or-later
// Filtered exact predicates on double coordinates (docs/ALGORITHM.md, "Exact").
//
// Each predicate evaluates its polynomial in double together with the same
// polynomial on absolute values (the "permanent" P). Evaluated as a tree of
// depth n on exact inputs, the rounding error is at most gamma_n * P with
// gamma_n = n u / (1 - n u), u = 2^-53 (Higham, "Accuracy and Stability",
// 3.1). We trust the double sign when |value| > (2n + 2) u P, which covers
// gamma_n, the rounding of P itself and of the bound; P must also lie in
// [2^-900, 2^+900] so that no underflow or overflow spoiled the analysis, and
// in the degree-4 ones underflow inside one product must stay below u P
// (filtered_sign's scale).
// Otherwise the polynomial is evaluated exactly (CGAL::Mpzf, exact for + - *),
// out of line in exact_fallback.cpp: the cold path.
#pragma once
#include <algorithm>
#include <cmath>

#include "lepp/pslg.h"

namespace lepp::fast {

namespace detail {
constexpr double kUnit = 1.1102230246251565e-16;  // 2^-53
constexpr double kTiny = 1.3e-271;                 // about 2^-900
constexpr double kHuge = 8.5e270;                  // about 2^+900
// Sign of value if the filter decides it, else 2.
//
// `scale`: underflow. A product or square whose value lies below 2^-1022 is off by
// up to 2^-1075 absolutely, not by u relatively (sums are exact there). In a
// polynomial of degree 2 that error stays far below the bound, since P >= 2^-900:
// scale 0. In one of degree 4 a subnormal product can be multiplied by a large
// factor (in-circle: a 2x2 minor by the lift of the third point, which P need not
// dominate; predicates_test's Underflow tests find wrong signs without this), so
// incircle and skinny_sign bound that error by 2^-1070 scale + 2^-1073. Where
// scale <= 2^1016 P that is at most u P (P >= 2^-900), which the bound's slack
// covers (it needs about (n + 1) u P: gamma_n for the value, u for the underflow;
// it is (2n + 2) u P); otherwise the exact path. The test is one multiplication in
// the normal range: an absolute term added to the bound would be subnormal, and
// subnormal arithmetic takes a microcode assist (it made incircle half again as slow).
inline int filtered_sign(double value, double permanent, int depth, double scale = 0) {
  if (!(permanent >= kTiny && permanent <= kHuge)) return 2;  // possible underflow/overflow: exact
  if (!(scale <= permanent * 0x1p1016)) return 2;              // underflow may exceed u P: exact
  double bound = (2 * depth + 2) * kUnit * permanent;
  if (value > bound) return 1;
  if (value < -bound) return -1;
  return 2;
}

int orient_exact(const Point& a, const Point& b, const Point& c);
int incircle_exact(const Point& a, const Point& b, const Point& c, const Point& d);
int compare_sqlen_exact(const Point& a, const Point& b, const Point& c, const Point& d);
int skinny_sign_exact(const Point& apex, const Point& b, const Point& c, double s);
int area_sign_exact(const Point& a, const Point& b, const Point& c, double twice_area);
int dot_sign_exact(const Point& v, const Point& a, const Point& b);
int sqlen_below_exact(const Point& a, const Point& b, double floor);
// sign(sin^2 of triangle a's smallest angle - sin^2 of triangle b's) (a, b: three points each).
int compare_sin2_exact(const Point* a, const Point* b);
}  // namespace detail

// Sign of the signed area of abc: +1 counter-clockwise, 0 collinear.
inline int orient(const Point& a, const Point& b, const Point& c) {
  double bax = b.x - a.x, bay = b.y - a.y, cax = c.x - a.x, cay = c.y - a.y;
  double l = bax * cay, r = bay * cax;
  int s = detail::filtered_sign(l - r, std::fabs(l) + std::fabs(r), 3);
  return s != 2 ? s : detail::orient_exact(a, b, c);
}

// +1 if d lies strictly inside the circle through the counter-clockwise a, b, c;
// 0 on it (four cocircular points); -1 outside.
inline int incircle(const Point& a, const Point& b, const Point& c, const Point& d) {
  double adx = a.x - d.x, ady = a.y - d.y, bdx = b.x - d.x, bdy = b.y - d.y, cdx = c.x - d.x, cdy = c.y - d.y;
  double bc1 = bdx * cdy, bc2 = cdx * bdy, ca1 = cdx * ady, ca2 = adx * cdy, ab1 = adx * bdy, ab2 = bdx * ady;
  double alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy, clift = cdx * cdx + cdy * cdy;
  double det = alift * (bc1 - bc2) + blift * (ca1 - ca2) + clift * (ab1 - ab2);
  double perm = alift * (std::fabs(bc1) + std::fabs(bc2)) + blift * (std::fabs(ca1) + std::fabs(ca2)) +
                clift * (std::fabs(ab1) + std::fabs(ab2));
  // Underflow: six minor products, each times a lift <= 2 L (L the largest lift, at
  // least every coordinate difference squared), six squares in the lifts, each times
  // a minor <= 2 L, three final products: at most (24 L + 3) 2^-1075, below
  // 2^-1070 L + 2^-1073 (filtered_sign's scale L).
  const double largest_lift = std::max(std::max(alift, blift), clift);
  int s = detail::filtered_sign(det, perm, 6, largest_lift);
  return s != 2 ? s : detail::incircle_exact(a, b, c, d);
}

inline double sqlen(const Point& a, const Point& b) {
  double dx = b.x - a.x, dy = b.y - a.y;
  return dx * dx + dy * dy;
}

// Sign of |ab|^2 - |cd|^2, exactly. lab, lcd: the double values of sqlen(a, b), sqlen(c, d).
inline int compare_sqlen(const Point& a, const Point& b, double lab, const Point& c, const Point& d, double lcd) {
  int s = detail::filtered_sign(lab - lcd, lab + lcd, 4);
  return s != 2 ? s : detail::compare_sqlen_exact(a, b, c, d);
}

// Sign of s * |b - apex|^2 * |c - apex|^2 - cross(b - apex, c - apex)^2.
inline int skinny_sign(const Point& apex, const Point& b, const Point& c, double s) {
  double ux = b.x - apex.x, uy = b.y - apex.y, vx = c.x - apex.x, vy = c.y - apex.y;
  double c1 = ux * vy, c2 = uy * vx;
  double cross = c1 - c2, pc = std::fabs(c1) + std::fabs(c2);
  double uu = ux * ux + uy * uy, vv = vx * vx + vy * vy;
  double rhs = s * (uu * vv);
  // Underflow (s <= 1): the squares in uu times s vv and in vv times s uu, the two
  // products of rhs, and cross's two products, whose error cross^2 carries times
  // 2 |cross| <= uu + vv: at most (uu + vv) 2^-1073 + 2^-1073 (filtered_sign's
  // scale uu + vv).
  // (Quality::judge_bits needs no such term: it tests the two longest sides, whose
  // squares are within 4 of each other, so a subnormal one makes P subnormal.)
  int sign = detail::filtered_sign(rhs - cross * cross, rhs + pc * pc, 6, uu + vv);
  return sign != 2 ? sign : detail::skinny_sign_exact(apex, b, c, s);
}

// Skinny test of ALGORITHM.md section 4 at the vertex apex opposite the shortest
// edge bc: true iff cross(b - apex, c - apex)^2 < s * |b - apex|^2 * |c - apex|^2.
inline bool skinny_at(const Point& apex, const Point& b, const Point& c, double s) {
  return skinny_sign(apex, b, c, s) > 0;
}

// Sign of |cross(b - a, c - a)| - twice_area.
inline int area_sign(const Point& a, const Point& b, const Point& c, double twice_area) {
  double bax = b.x - a.x, bay = b.y - a.y, cax = c.x - a.x, cay = c.y - a.y;
  double l = bax * cay, r = bay * cax;
  double value = std::fabs(l - r) - twice_area;
  int s = detail::filtered_sign(value, std::fabs(l) + std::fabs(r) + twice_area, 4);
  return s != 2 ? s : detail::area_sign_exact(a, b, c, twice_area);
}

// Size test: |cross(b - a, c - a)| > twice_area, exactly.
inline bool area_above(const Point& a, const Point& b, const Point& c, double twice_area) {
  return area_sign(a, b, c, twice_area) > 0;
}

// Sign of dot(a - v, b - v).
inline int dot_sign(const Point& v, const Point& a, const Point& b) {
  double l = (a.x - v.x) * (b.x - v.x), r = (a.y - v.y) * (b.y - v.y);
  int s = detail::filtered_sign(l + r, std::fabs(l) + std::fabs(r), 3);
  return s != 2 ? s : detail::dot_sign_exact(v, a, b);
}

// Sign of floor^2 - |ab|^2, exactly (floor^2 as the rational it is, not rounded).
inline int sqlen_below_sign(const Point& a, const Point& b, double floor) {
  double l = sqlen(a, b), f = floor * floor;
  int s = detail::filtered_sign(f - l, f + l, 4);
  return s != 2 ? s : detail::sqlen_below_exact(a, b, floor);
}

// |ab|^2 < floor^2, exactly.
inline bool sqlen_below(const Point& a, const Point& b, double floor) { return sqlen_below_sign(a, b, floor) > 0; }

}  // namespace lepp::fast
