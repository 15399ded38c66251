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
