// SPDX-License-Identifier: GPL-3.0-or-later
// The exact paths of the filtered predicates of double_predicates.h, out of
// line: the filters' cold path.
#include "double_predicates.h"

#include <CGAL/Mpzf.h>

namespace lepp::reference::detail {

namespace {
using E = CGAL::Mpzf;  // exact for +, - and *: its exponent is unbounded (subnormals, 1e300 squared)
}  // namespace

int compare_squared_lengths_exact(const Point& a, const Point& b, const Point& c, const Point& d) {
  const E abx = E(a.x) - E(b.x), aby = E(a.y) - E(b.y), cdx = E(c.x) - E(d.x), cdy = E(c.y) - E(d.y);
  return (abx * abx + aby * aby - (cdx * cdx + cdy * cdy)).sign();
}

int skinny_sign_exact(const Point& apex, const Point& b, const Point& c, double sin2) {
  const E ax(apex.x), ay(apex.y);
  const E ux = E(b.x) - ax, uy = E(b.y) - ay, vx = E(c.x) - ax, vy = E(c.y) - ay;
  const E cross = ux * vy - uy * vx;
  return (E(sin2) * ((ux * ux + uy * uy) * (vx * vx + vy * vy)) - cross * cross).sign();
}

}  // namespace lepp::reference::detail
