// SPDX-License-Identifier: GPL-3.0-or-later
// Exact tests of a chain vertex against its segment AB: within a tolerance, near the line, ahead, straighter.
#pragma once
#include <cmath>

#include "../exact.h"

namespace lepp::certify {

// |cross(B - A, P - A)| <= tol * (|B.x - A.x| + |B.y - A.y|), exactly.
inline bool within(const Point& a, const Point& b, const Point& p, double tol) {
  return exact::sign([&](auto z) -> decltype(z) {
           using NT = decltype(z);
           NT dx = NT(b.x) - NT(a.x), dy = NT(b.y) - NT(a.y);
           NT cross = dx * (NT(p.y) - NT(a.y)) - dy * (NT(p.x) - NT(a.x));
           return CGAL::abs(cross) - NT(tol) * (CGAL::abs(dx) + CGAL::abs(dy));
         }) <= 0;
}
// |cross(B - A, P - A)| <= 2^-20 |AB|^2: P within 2^-20 |AB| of the line (to follow listed edges).
inline bool near_line(const Point& a, const Point& b, const Point& p) {
  return exact::sign([&](auto z) -> decltype(z) {
           using NT = decltype(z);
           NT dx = NT(b.x) - NT(a.x), dy = NT(b.y) - NT(a.y);
           NT cross = dx * (NT(p.y) - NT(a.y)) - dy * (NT(p.x) - NT(a.x));
           return CGAL::abs(cross) - NT(std::ldexp(1.0, -20)) * (dx * dx + dy * dy);
         }) <= 0;
}
// The step from p to q turns less from AB than the step from p to r (both ahead):
// |cross(B - A, q - p)| / dot(B - A, q - p) < |cross(B - A, r - p)| / dot(B - A, r - p), exactly.
inline int compare_turn(const Point& a, const Point& b, const Point& p, const Point& q, const Point& r) {
  return exact::sign([&](auto z) -> decltype(z) {
    using NT = decltype(z);
    NT dx = NT(b.x) - NT(a.x), dy = NT(b.y) - NT(a.y);
    NT qx = NT(q.x) - NT(p.x), qy = NT(q.y) - NT(p.y), rx = NT(r.x) - NT(p.x), ry = NT(r.y) - NT(p.y);
    return CGAL::abs(dx * qy - dy * qx) * (dx * rx + dy * ry) - CGAL::abs(dx * ry - dy * rx) * (dx * qx + dy * qy);
  });
}
// sign(dot(q - p, B - A)): q ahead of p along AB.
inline int ahead(const Point& a, const Point& b, const Point& p, const Point& q) {
  return exact::sign([&](auto z) -> decltype(z) {
    using NT = decltype(z);
    return (NT(q.x) - NT(p.x)) * (NT(b.x) - NT(a.x)) + (NT(q.y) - NT(p.y)) * (NT(b.y) - NT(a.y));
  });
}

}  // namespace lepp::certify
