// SPDX-License-Identifier: GPL-3.0-or-later
// The distance from a point to a closed segment, in doubles: it only sizes guards
// (the default edge floor, the fuzzers' loop guard), never decides geometry.
#pragma once

#include <algorithm>
#include <cmath>

#include "lepp/pslg.h"

namespace lepp {

inline double distance_to_segment(const Point& p, const Point& a, const Point& b) {
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

}  // namespace lepp
