// SPDX-License-Identifier: GPL-3.0-or-later
// The exact path of the filtered predicates (predicates.h): the same
// polynomials in CGAL::Mpzf, which is exact for +, - and * on doubles.
#include <CGAL/Mpzf.h>

#include "predicates.h"

namespace lepp::fast::detail {
namespace {
using E = CGAL::Mpzf;
int sign_of(const E& x) { return x.sign(); }
}  // namespace

int orient_exact(const Point& a, const Point& b, const Point& c) {
  E ax(a.x), ay(a.y);
  return sign_of((E(b.x) - ax) * (E(c.y) - ay) - (E(b.y) - ay) * (E(c.x) - ax));
}

int incircle_exact(const Point& a, const Point& b, const Point& c, const Point& d) {
  E dx(d.x), dy(d.y);
  E adx = E(a.x) - dx, ady = E(a.y) - dy, bdx = E(b.x) - dx, bdy = E(b.y) - dy, cdx = E(c.x) - dx, cdy = E(c.y) - dy;
  E alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy, clift = cdx * cdx + cdy * cdy;
  return sign_of(alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) + clift * (adx * bdy - bdx * ady));
}

int compare_sqlen_exact(const Point& a, const Point& b, const Point& c, const Point& d) {
  E abx = E(b.x) - E(a.x), aby = E(b.y) - E(a.y), cdx = E(d.x) - E(c.x), cdy = E(d.y) - E(c.y);
  return sign_of((abx * abx + aby * aby) - (cdx * cdx + cdy * cdy));
}

int skinny_sign_exact(const Point& apex, const Point& b, const Point& c, double s) {
  E px(apex.x), py(apex.y);
  E ux = E(b.x) - px, uy = E(b.y) - py, vx = E(c.x) - px, vy = E(c.y) - py;
  E cross = ux * vy - uy * vx;
  return sign_of(E(s) * ((ux * ux + uy * uy) * (vx * vx + vy * vy)) - cross * cross);
}

int area_sign_exact(const Point& a, const Point& b, const Point& c, double twice_area) {
  E ax(a.x), ay(a.y);
  E cross = (E(b.x) - ax) * (E(c.y) - ay) - (E(b.y) - ay) * (E(c.x) - ax);
  if (cross.sign() < 0) cross = -cross;
  return sign_of(cross - E(twice_area));
}

int dot_sign_exact(const Point& v, const Point& a, const Point& b) {
  E vx(v.x), vy(v.y);
  return sign_of((E(a.x) - vx) * (E(b.x) - vx) + (E(a.y) - vy) * (E(b.y) - vy));
}

int sqlen_below_exact(const Point& a, const Point& b, double floor) {
  E dx = E(b.x) - E(a.x), dy = E(b.y) - E(a.y), f(floor);
  return sign_of(f * f - (dx * dx + dy * dy));
}

}  // namespace lepp::fast::detail

namespace lepp::fast::detail {
namespace {
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
}  // namespace

int compare_sin2_exact(const Point* a, const Point* b) {
  E ca, ma, cb, mb;
  sin2_terms(a, ca, ma);
  sin2_terms(b, cb, mb);
  return sign_of(ca * mb - cb * ma);
}

}  // namespace lepp::fast::detail
