// SPDX-License-Identifier: GPL-3.0-or-later
// Private to the conformance replay: whether a program's point is surely farther than
// a tolerance from an exact candidate, decided without exact arithmetic. Most
// candidates lie far from the program's point, and their exact differences (lazy
// nodes, then GMP rationals) were a third of the allocations of fuzz_engine's parent,
// each an allocation stack under ASan, and time in every `lepp audit`.
#pragma once
#include <cmath>

#include "lepp/pslg.h"
#include "triangulation.h"  // reference/src: the exact engine's CGAL types

namespace lepp::audit::replay_detail {

using namespace lepp::reference::detail;

// True only when the exact |p.x - q.x| or |p.y - q.y| exceeds tol, read from q's
// interval approximation with outward rounding; then the replay's distance (each
// difference rounded to a double, the larger) exceeds tol too, rounding being monotone
// and tol a double. False says nothing: the exact distance decides. A p that is not
// finite is left to it as well.
inline bool surely_farther(const Point& p, const CPoint& q, double tol) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
  using I = CGAL::Interval_nt<true>;
  const auto& a = CGAL::approx(q);
  auto beyond = [tol](double v, const auto& x) {
    const I d = I(v) - I(x.inf(), x.sup());
    return d.inf() > tol || d.sup() < -tol;
  };
  return beyond(p.x, a.x()) || beyond(p.y, a.y());
}

}  // namespace lepp::audit::replay_detail
