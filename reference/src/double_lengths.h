// SPDX-License-Identifier: GPL-3.0-or-later
// Private to the reference engine: exact comparison of the squared lengths of
// two edges whose endpoints are doubles (every vertex of the triangulation is).
// Lazy Epeck builds a node per squared distance and, where its intervals cannot
// decide (lengths that tie, or squares below the doubles' range: a cluster a
// few ulps wide), an exact Gmpq with gcds; most of the engine's time on such
// clusters (issue 28). Here: a double filter, then the exact value in
// CGAL::Mpzf (exact for +, - and * on doubles, no gcd).
#pragma once
#include <cmath>

#include "lepp/pslg.h"

namespace lepp::reference::detail {

// sign(|ab|^2 - |cd|^2) exactly, with no filter: the exact path, and the
// oracle of the filter in the tests.
int compare_squared_lengths_exact(const Point& a, const Point& b, const Point& c, const Point& d);

// sign(|ab|^2 - |cd|^2) exactly: -1, 0 or +1.
inline int compare_squared_lengths(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double abx = a.x - b.x, aby = a.y - b.y, cdx = c.x - d.x, cdy = c.y - d.y;
  const double lab = abx * abx + aby * aby, lcd = cdx * cdx + cdy * cdy;
  // Each computed length is within 4.01u of its exact value (u = 2^-53; one
  // rounded difference, one square, one sum), plus at most three underflows of
  // 2^-1075 each. Trusted only where the larger is between 2^-900 and 2^1000:
  // no overflow, and the underflows far below the margin of 8u (lab + lcd).
  const double big = std::fmax(lab, lcd);
  if (big >= 0x1p-900 && big <= 0x1p1000) {
    const double margin = 8 * 0x1p-53 * (lab + lcd);
    if (lab - lcd > margin) return 1;
    if (lcd - lab > margin) return -1;
  }
  return compare_squared_lengths_exact(a, b, c, d);
}

}  // namespace lepp::reference::detail
