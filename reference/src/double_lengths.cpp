// SPDX-License-Identifier: GPL-3.0-or-later
// The exact path of compare_squared_lengths (double_lengths.h), out of line:
// the cold path of the filter.
#include "double_lengths.h"

#include <CGAL/Mpzf.h>

namespace lepp::reference::detail {

int compare_squared_lengths_exact(const Point& a, const Point& b, const Point& c, const Point& d) {
  using E = CGAL::Mpzf;  // exact: its exponent is unbounded, subnormals and 1e300 squared included
  const E abx = E(a.x) - E(b.x), aby = E(a.y) - E(b.y), cdx = E(c.x) - E(d.x), cdy = E(c.y) - E(d.y);
  return (abx * abx + aby * aby - (cdx * cdx + cdy * cdy)).sign();
}

}  // namespace lepp::reference::detail
