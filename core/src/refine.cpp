// SPDX-License-Identifier: GPL-3.0-or-later
// Names of the shared enums and the loop guards' defaults (ALGORITHM.md, "Termination").
#include "lepp/refine.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lepp {

std::int64_t default_steiner_budget(const Pslg& pslg, const RefineOptions& options) {
  // Generous for every converging run we have seen (the paper's problems need
  // at most a few thousand points at 36 degrees) yet a hard stop for a cascade.
  std::int64_t n = static_cast<std::int64_t>(pslg.vertices.size() + pslg.segments.size());
  std::int64_t budget = 100000 + 1000 * n;
  if (options.max_area > 0 && !pslg.vertices.empty()) {
    double x0 = pslg.vertices[0].x, x1 = x0, y0 = pslg.vertices[0].y, y1 = y0;
    for (const Point& p : pslg.vertices) {
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
      y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
    // A mesh of triangles of area max_area/4 covering the bounding box, twice over.
    double size_points = 8.0 * (x1 - x0) * (y1 - y0) / options.max_area;
    budget += static_cast<std::int64_t>(std::min(size_points, 4e9));
  }
  return budget;
}

double default_edge_floor(const Pslg& pslg) {
  double shortest = std::numeric_limits<double>::infinity();
  for (const Segment& s : pslg.segments) {
    const Point& a = pslg.vertices[static_cast<std::size_t>(s.a)];
    const Point& b = pslg.vertices[static_cast<std::size_t>(s.b)];
    shortest = std::min(shortest, std::hypot(a.x - b.x, a.y - b.y));
  }
  if (!std::isfinite(shortest)) return 0;
  return std::ldexp(shortest, -20);  // a million times shorter than the shortest input segment
}

const char* to_string(Outcome outcome) {
  switch (outcome) {
    case Outcome::Converged: return "converged";
    case Outcome::Unimprovable: return "unimprovable";
    case Outcome::SteinerBudget: return "steiner-budget";
    case Outcome::EdgeFloor: return "edge-floor";
    case Outcome::TimeLimit: return "time-limit";
  }
  return "?";
}

const char* to_string(Rule rule) {
  switch (rule) {
    case Rule::TerminalConstrainedMidpoint: return "terminal-constrained-midpoint";
    case Rule::TerminalMidpoint: return "terminal-midpoint";
    case Rule::SecondLongestMidpoint: return "second-longest-midpoint";
    case Rule::QuadCentroid: return "quad-centroid";
    case Rule::CentroidInOther: return "centroid-in-other";
    case Rule::BothSecondLongestMidpoint: return "both-second-longest-midpoint";
  }
  return "?";
}

const char* to_string(Method method) { return method == Method::Centroid ? "centroid" : "midpoint"; }
const char* to_string(QueueOrder order) { return order == QueueOrder::Fifo ? "fifo" : "lifo"; }

int exit_status(Outcome outcome) { return outcome == Outcome::Converged ? 0 : 3; }

}  // namespace lepp
