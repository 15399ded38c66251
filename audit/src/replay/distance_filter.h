// SPDX-License-Identifier: GPL-3.0-or-later
// Private to the conformance replay: whether a program's point is surely farther than
// a tolerance from an exact candidate, decided without exact arithmetic. Most
// candidates lie far from the program's point, and their exact differences (lazy
// nodes, then GMP rationals) were a third of the allocations of fuzz_engine's parent,
// each an allocation stack under ASan, and time in every `lepp audit`.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>

#include "lepp/pslg.h"
#include "triangulation.h"  // reference/src: the exact engine's CGAL types

namespace lepp::audit::replay_detail {

using namespace lepp::reference::detail;

// True only when the exact |p.x - q.x| or |p.y - q.y| exceeds tol, read from q's
// interval approximation with outward rounding; then the replay's distance (each
// difference rounded to a double, the larger) exceeds tol too, rounding being monotone
// and tol a double. False says nothing: the exact distance decides. A p that is not
// finite is left to it as well.
// The same from intervals enclosing the point's coordinates.
inline bool surely_farther(const Point& p, const CGAL::Interval_nt<true>& x, const CGAL::Interval_nt<true>& y, double tol) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
  using I = CGAL::Interval_nt<true>;
  auto beyond = [tol](double v, const I& q) {
    const I d = I(v) - q;
    return d.inf() > tol || d.sup() < -tol;
  };
  return beyond(p.x, x) || beyond(p.y, y);
}

inline bool surely_farther(const Point& p, const CPoint& q, double tol) {
  using I = CGAL::Interval_nt<true>;
  const auto& a = CGAL::approx(q);
  return surely_farther(p, I(a.x().inf(), a.x().sup()), I(a.y().inf(), a.y().sup()), tol);
}

// The box around some exact points, from their interval approximations: every point
// made of them with non-negative weights summing to one (a midpoint, a centroid of
// either reading) lies in it. It bounds a whole terminal configuration's candidates
// before any is constructed: in the whole-mesh searches most configurations lie far
// from the program's point, and building their exact candidates (lazy nodes, GMP)
// was most of the catalogue's diagnosis.
struct ApproxBox {
  double xlo = std::numeric_limits<double>::infinity(), xhi = -std::numeric_limits<double>::infinity();
  double ylo = xlo, yhi = xhi;

  void add(const CPoint& q) {
    const auto& a = CGAL::approx(q);
    xlo = std::min(xlo, a.x().inf()), xhi = std::max(xhi, a.x().sup());
    ylo = std::min(ylo, a.y().inf()), yhi = std::max(yhi, a.y().sup());
  }
  // The largest |coordinate| in the box: at least abs_max of each point added.
  double abs_max() const { return std::max({std::abs(xlo), std::abs(xhi), std::abs(ylo), std::abs(yhi)}); }

  // No more than the replay's distance (Replayer::distance) from p to any point in the
  // box: the exact gap on each axis rounded down, lowered by 2^-10 of itself. The
  // replay rounds each exact difference through CGAL's to_double, which may return the
  // midpoint of an interval up to 1e-5 wide relative to the value (CGAL's relative
  // precision of to_double), so a little below the exact gap. 0 for a p that is not
  // finite or an empty box (nothing said).
  double lower_bound(const Point& p) const {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !(xlo <= xhi) || !(ylo <= yhi)) return 0;
    using I = CGAL::Interval_nt<true>;
    auto gap = [](double v, double lo, double hi) {
      return std::max({0.0, (I(lo) - I(v)).inf(), (I(v) - I(hi)).inf()});
    };
    const double g = std::max(gap(p.x, xlo, xhi), gap(p.y, ylo, yhi));
    return g - g * 0x1p-10;
  }
};

}  // namespace lepp::audit::replay_detail
