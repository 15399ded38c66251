// SPDX-License-Identifier: GPL-3.0-or-later
// The exact path of the filtered predicates (predicates.h): the same
// polynomials in doubles where every step is exact (exact_doubles.h: most ties
// on grid inputs), else in CGAL::Mpzf, which is exact for +, - and * on doubles.
#include <CGAL/Mpzf.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>

#include "exact_doubles.h"
#include "predicates.h"

namespace lepp::fast::detail {
namespace {
using E = CGAL::Mpzf;
int sign_of(const E& x) { return x.sign(); }

int orient_mpzf(const Point& a, const Point& b, const Point& c) {
  E ax(a.x), ay(a.y);
  return sign_of((E(b.x) - ax) * (E(c.y) - ay) - (E(b.y) - ay) * (E(c.x) - ax));
}

int incircle_mpzf(const Point& a, const Point& b, const Point& c, const Point& d) {
  E dx(d.x), dy(d.y);
  E adx = E(a.x) - dx, ady = E(a.y) - dy, bdx = E(b.x) - dx, bdy = E(b.y) - dy, cdx = E(c.x) - dx, cdy = E(c.y) - dy;
  E alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy, clift = cdx * cdx + cdy * cdy;
  return sign_of(alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) + clift * (adx * bdy - bdx * ady));
}

int compare_sqlen_mpzf(const Point& a, const Point& b, const Point& c, const Point& d) {
  E abx = E(b.x) - E(a.x), aby = E(b.y) - E(a.y), cdx = E(d.x) - E(c.x), cdy = E(d.y) - E(c.y);
  return sign_of((abx * abx + aby * aby) - (cdx * cdx + cdy * cdy));
}

int skinny_sign_mpzf(const Point& apex, const Point& b, const Point& c, double s) {
  E px(apex.x), py(apex.y);
  E ux = E(b.x) - px, uy = E(b.y) - py, vx = E(c.x) - px, vy = E(c.y) - py;
  E cross = ux * vy - uy * vx;
  return sign_of(E(s) * ((ux * ux + uy * uy) * (vx * vx + vy * vy)) - cross * cross);
}

int area_sign_mpzf(const Point& a, const Point& b, const Point& c, double twice_area) {
  E ax(a.x), ay(a.y);
  E cross = (E(b.x) - ax) * (E(c.y) - ay) - (E(b.y) - ay) * (E(c.x) - ax);
  if (cross.sign() < 0) cross = -cross;
  return sign_of(cross - E(twice_area));
}

int dot_sign_mpzf(const Point& v, const Point& a, const Point& b) {
  E vx(v.x), vy(v.y);
  return sign_of((E(a.x) - vx) * (E(b.x) - vx) + (E(a.y) - vy) * (E(b.y) - vy));
}

int sqlen_below_mpzf(const Point& a, const Point& b, double floor) {
  E dx = E(b.x) - E(a.x), dy = E(b.y) - E(a.y), f(floor);
  return sign_of(f * f - (dx * dx + dy * dy));
}

// cross^2 and M (the largest product of two squared edge lengths) of triangle t, exactly.
void sin2_terms(const Point* t, E& cross2, E& m) {
  E ax(t[0].x), ay(t[0].y);
  E ux = E(t[1].x) - ax, uy = E(t[1].y) - ay, vx = E(t[2].x) - ax, vy = E(t[2].y) - ay;
  E wx = E(t[2].x) - E(t[1].x), wy = E(t[2].y) - E(t[1].y);
  E cross = ux * vy - uy * vx;
  cross2 = cross * cross;
  E la = ux * ux + uy * uy, lb = vx * vx + vy * vy, lc = wx * wx + wy * wy;
  E p[3] = {la * lb, la * lc, lb * lc};
  m = p[0];
  for (int i = 1; i < 3; ++i)
    if ((p[i] - m).sign() > 0) m = p[i];
}

int compare_sin2_mpzf(const Point* a, const Point* b) {
  E ca, ma, cb, mb;
  sin2_terms(a, ca, ma);
  sin2_terms(b, cb, mb);
  return sign_of(ca * mb - cb * ma);
}

// The filter refuses a permanent below 2^-900 (underflow could spoil its bound):
// points near the origin (subnormal clusters, or a refinement walking down to
// them) fail it whatever their configuration, and their products leave the
// doubles' range. Scaling every coordinate by 2^k is exact when the largest
// lands in [1, 2) (no overflow; subnormals scale exactly), and every polynomial
// here is homogeneous in the coordinates (a constant of length or area scales
// with them), so its sign on the scaled points is the same. 2^k (k up to 1074)
// is applied as two factors, each a double; no scale (k = 0): not tiny.
struct Scale {
  int k = 0;
  double f1 = 1, f2 = 1;  // f1 * f2 = 2^k
  double of(double v) const { return v * f1 * f2; }
  Point of(const Point& p) const { return {of(p.x), of(p.y)}; }
};
// 2^j for j in [0, 1023], from its bits (ldexp is a library call on a hot path here).
double power_of_two(int j) {
  const std::uint64_t bits = static_cast<std::uint64_t>(1023 + j) << 52;
  double v;
  std::memcpy(&v, &bits, sizeof v);
  return v;
}
Scale tiny_scale(std::initializer_list<Point> points) {
  double m = 0;
  for (const Point& p : points) {
    const double ax = std::fabs(p.x), ay = std::fabs(p.y);
    m = ax > m ? ax : m;
    m = ay > m ? ay : m;
  }
  if (!(m > 0 && m < 1)) return {};
  const int k = -std::ilogb(m);  // 1 to 1074
  return {k, power_of_two(k / 2), power_of_two(k - k / 2)};
}
}  // namespace

// Each: on tiny points, the filter again at scale (its own fallback then finds
// no scale); then the polynomial in doubles if every step is exact; then Mpzf.
// The orientation and the length comparison try an exact sum before Mpzf
// (exact_doubles.h); it decides every case the doubles' step decides, which
// stays first as the cheaper one (most filter failures are exact ties on grids).
int orient_exact(const Point& a, const Point& b, const Point& c) {
  if (const Scale t = tiny_scale({a, b, c}); t.k) return orient(t.of(a), t.of(b), t.of(c));
  if (const int s = orient_in_doubles(a, b, c); s != 2) return s;
  const int s = orient_by_expansion(a, b, c);
  return s != 2 ? s : orient_mpzf(a, b, c);
}

int incircle_exact(const Point& a, const Point& b, const Point& c, const Point& d) {
  if (const Scale t = tiny_scale({a, b, c, d}); t.k) return incircle(t.of(a), t.of(b), t.of(c), t.of(d));
  const int s = incircle_in_doubles(a, b, c, d);
  return s != 2 ? s : incircle_mpzf(a, b, c, d);
}

int compare_sqlen_exact(const Point& a, const Point& b, const Point& c, const Point& d) {
  if (const int s = compare_sqlen_by_dominance(a, b, c, d); s != 2) return s;  // exact at any scale
  if (const Scale t = tiny_scale({a, b, c, d}); t.k) {
    const Point sa = t.of(a), sb = t.of(b), sc = t.of(c), sd = t.of(d);
    return compare_sqlen(sa, sb, sqlen(sa, sb), sc, sd, sqlen(sc, sd));
  }
  if (const int s = compare_sqlen_in_doubles(a, b, c, d); s != 2) return s;
  const int s = compare_sqlen_by_expansion(a, b, c, d);
  return s != 2 ? s : compare_sqlen_mpzf(a, b, c, d);
}

int dot_sign_exact(const Point& v, const Point& a, const Point& b) {
  if (const Scale t = tiny_scale({v, a, b}); t.k) return dot_sign(t.of(v), t.of(a), t.of(b));
  const int s = dot_sign_in_doubles(v, a, b);
  return s != 2 ? s : dot_sign_mpzf(v, a, b);
}

int skinny_sign_exact(const Point& apex, const Point& b, const Point& c, double s) {
  // s, a ratio (sin^2 of theta), does not scale.
  if (const Scale t = tiny_scale({apex, b, c}); t.k) return skinny_sign(t.of(apex), t.of(b), t.of(c), s);
  const int sign = skinny_sign_in_doubles(apex, b, c, s);
  return sign != 2 ? sign : skinny_sign_mpzf(apex, b, c, s);
}

int area_sign_exact(const Point& a, const Point& b, const Point& c, double twice_area) {
  // An area scales by 2^(2k): exactly while it stays finite.
  if (const Scale t = tiny_scale({a, b, c}); t.k && std::isfinite(t.of(t.of(twice_area))))
    return area_sign(t.of(a), t.of(b), t.of(c), t.of(t.of(twice_area)));
  const int s = area_sign_in_doubles(a, b, c, twice_area);
  return s != 2 ? s : area_sign_mpzf(a, b, c, twice_area);
}

int sqlen_below_exact(const Point& a, const Point& b, double floor) {
  if (const Scale t = tiny_scale({a, b}); t.k && std::isfinite(t.of(floor)))
    return sqlen_below_sign(t.of(a), t.of(b), t.of(floor));
  const int s = sqlen_below_in_doubles(a, b, floor);
  return s != 2 ? s : sqlen_below_mpzf(a, b, floor);
}

int compare_sin2_exact(const Point* a, const Point* b) {
  // sin^2 is a ratio of degree 4 to degree 4: each triangle takes its own scale.
  const Scale ta = tiny_scale({a[0], a[1], a[2]}), tb = tiny_scale({b[0], b[1], b[2]});
  const Point sa[3] = {ta.of(a[0]), ta.of(a[1]), ta.of(a[2])};
  const Point sb[3] = {tb.of(b[0]), tb.of(b[1]), tb.of(b[2])};
  const int s = compare_sin2_in_doubles(sa, sb);
  return s != 2 ? s : compare_sin2_mpzf(a, b);
}

}  // namespace lepp::fast::detail
