// SPDX-License-Identifier: GPL-3.0-or-later
// The arithmetic of the limit of double precision (ALGORITHM.md section 8b),
// written once for the fast engine, the reference and the certifier: the doubles
// around an exact midpoint or centroid coordinate, and the precision floor.
#pragma once
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstddef>

#include "lepp/pslg.h"

namespace lepp {

// One or two doubles, ascending; iterable.
struct DoublesAround {
  double value[2] = {0, 0};
  int count = 0;
  const double* begin() const { return value; }
  const double* end() const { return value + count; }
};

// The doubles next to the exact mean of the n doubles xs (n = 2: a midpoint's
// coordinate; n = 4: a centroid's), computed exactly (GMP rationals): the mean
// itself when it is a double, else the one below and the one above it.
DoublesAround doubles_around_mean(const double* xs, int n);
inline DoublesAround doubles_around_midpoint(double a, double b) {
  const double xs[2] = {a, b};
  return doubles_around_mean(xs, 2);
}
inline DoublesAround doubles_around_centroid(double a, double b, double c, double d) {
  const double xs[4] = {a, b, c, d};
  return doubles_around_mean(xs, 4);
}

// The default bound of the search of every resolution of exact length ties at the
// precision limit (ALGORITHM.md section 8b): Lepp states (a triangle with one of its
// edges taken as its longest) per triangle, the same in both engines, the certifier,
// the audit and Python (RefineOptions::tie_search_states, certify::Options::
// tie_search_states, --tie-search-states). Beyond it an engine leaves the triangle
// and the certifier calls the claim undecided at that bound.
constexpr std::size_t kTieSearchStates = 1024;

namespace detail {
bool below_precision_floor_exact(const Point& a, const Point& b);
}

// The precision floor of an edge (ALGORITHM.md section 8b): true iff |a - b| is
// below 4 ulps of the largest magnitude of their coordinates, decided as
// detail::below_precision_floor_exact says. Far from the limit (a coordinate
// difference of at least M * 2^-50 >= 4 ulp(M), M the largest magnitude, both
// exact while M * 2^-50 is normal) it answers without computing the ulp: the
// engines ask on every insertion.
inline bool below_precision_floor(const Point& a, const Point& b) {
  const double m = std::max(std::max(std::fabs(a.x), std::fabs(a.y)), std::max(std::fabs(b.x), std::fabs(b.y)));
  const double far = m * 0x1p-50;
  if (far >= DBL_MIN && (std::fabs(a.x - b.x) >= far || std::fabs(a.y - b.y) >= far)) return false;
  return detail::below_precision_floor_exact(a, b);
}

}  // namespace lepp
