// SPDX-License-Identifier: GPL-3.0-or-later
// The sliver clause of the precision stop (ALGORITHM.md section 8b): a split of a
// domain-boundary edge ab at a rounded midpoint p strictly outside it
// (orient(a, b, p) < 0, half an ulp off the line) also covers the closed thin
// triangle a, p, b beyond the boundary. It is insertable only if no input vertex
// outside the domain lies in that triangle and no input segment outside the
// domain meets it. Header-only, the geometry written once for the fast engine and
// the certifier, each with its own exact orientation predicate (the reference
// decides it on its CGAL triangulation: reference/src/select_point.cpp).
#pragma once
#include <algorithm>
#include <array>
#include <vector>

#include "lepp/pslg.h"

namespace lepp {

// The input outside the domain: the vertices on no domain triangle and the
// segments with the domain on neither side, as coordinates.
struct OutsideInput {
  std::vector<Point> vertices;
  std::vector<std::array<Point, 2>> segments;
};

namespace detail {
// w, collinear with u and v, lies in their closed bounding box (so on the closed segment).
inline bool in_box(const Point& u, const Point& v, const Point& w) {
  return std::min(u.x, v.x) <= w.x && w.x <= std::max(u.x, v.x) && std::min(u.y, v.y) <= w.y && w.y <= std::max(u.y, v.y);
}
}  // namespace detail

// The closed segments p1p2 and q1q2 share a point (orient: exact sign of the
// orientation determinant, -1, 0 or 1).
template <class Orient>
bool closed_segments_meet(const Point& p1, const Point& p2, const Point& q1, const Point& q2, Orient orient) {
  const int d1 = orient(p1, p2, q1), d2 = orient(p1, p2, q2), d3 = orient(q1, q2, p1), d4 = orient(q1, q2, p2);
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;
  return (d1 == 0 && detail::in_box(p1, p2, q1)) || (d2 == 0 && detail::in_box(p1, p2, q2)) ||
         (d3 == 0 && detail::in_box(q1, q2, p1)) || (d4 == 0 && detail::in_box(q1, q2, p2));
}

// True iff the closed triangle a, p, b (counter-clockwise: p strictly right of
// a -> b) holds a vertex of `outside` other than a and b, or an outside segment
// meets it: one ending at a (or b) that leaves into the triangle's angle there,
// any other that has an endpoint in it or meets the closed side ap or pb. The
// same tests as the reference's scan of its whole triangulation, on fewer items.
template <class Orient>
bool sliver_blocked(const OutsideInput& outside, const Point& a, const Point& b, const Point& p, Orient orient) {
  auto in_closed = [&](const Point& q) { return orient(a, p, q) >= 0 && orient(p, b, q) >= 0 && orient(b, a, q) >= 0; };
  for (const Point& q : outside.vertices)
    if (q != a && q != b && in_closed(q)) return true;
  for (const auto& s : outside.segments) {
    Point u = s[0], w = s[1];
    if ((u == a && w == b) || (u == b && w == a)) continue;
    if (w == a || w == b) std::swap(u, w);
    if (u == a) {
      if (orient(a, b, w) < 0 && orient(a, p, w) >= 0) return true;
    } else if (u == b) {
      if (orient(a, b, w) < 0 && orient(p, b, w) >= 0) return true;
    } else if (in_closed(u) || in_closed(w) || closed_segments_meet(u, w, a, p, orient) || closed_segments_meet(u, w, p, b, orient)) {
      return true;
    }
  }
  return false;
}

}  // namespace lepp
