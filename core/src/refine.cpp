// SPDX-License-Identifier: GPL-3.0-or-later
// Names of the shared enums and the loop guards' defaults (ALGORITHM.md, "Termination").
#include "lepp/refine.h"

#include "lepp/segment_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <thread>
#include <vector>

namespace lepp {

int threads_or_cores(int threads) {
  return threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

std::int64_t default_steiner_budget(const Pslg& pslg, const RefineOptions& options) {
  // Generous for every converging run we have seen (the paper's problems need
  // at most a few thousand points at 36 degrees) yet a hard stop for a cascade.
  std::int64_t n = static_cast<std::int64_t>(pslg.vertices.size() + pslg.segments.size());
  std::int64_t budget = 100000 + 1000 * n;
  // The smallest size bound in force: the global one, or a region's (with region_area_bounds).
  double smallest = options.max_area > 0 ? options.max_area : 0;
  if (options.region_area_bounds)
    for (const Region& r : pslg.regions)
      if (r.max_area > 0 && (smallest <= 0 || r.max_area < smallest)) smallest = r.max_area;
  if (smallest > 0 && !pslg.vertices.empty()) {
    double x0 = pslg.vertices[0].x, x1 = x0, y0 = pslg.vertices[0].y, y1 = y0;
    for (const Point& p : pslg.vertices) {
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
      y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
    // A mesh of triangles of area smallest/4 covering the bounding box, twice over.
    double size_points = 8.0 * (x1 - x0) * (y1 - y0) / smallest;
    budget += static_cast<std::int64_t>(std::min(size_points, 4e9));
  }
  return budget;
}

namespace {

// The input's smallest feature: the shortest segment, the closest two vertices,
// and the closest vertex to a segment it does not end (zero distances, which a
// validated input does not have, are skipped). Vertices sorted by x and pruned
// by the best distance so far: near n log n on spread-out input.
double smallest_feature(const Pslg& pslg) {
  const auto& v = pslg.vertices;
  double best = std::numeric_limits<double>::infinity();
  auto keep = [&](double d) {
    if (d > 0 && d < best) best = d;
  };
  for (const Segment& s : pslg.segments)
    keep(std::hypot(v[static_cast<std::size_t>(s.a)].x - v[static_cast<std::size_t>(s.b)].x,
                    v[static_cast<std::size_t>(s.a)].y - v[static_cast<std::size_t>(s.b)].y));
  std::vector<std::size_t> by_x(v.size());
  for (std::size_t i = 0; i < by_x.size(); ++i) by_x[i] = i;
  std::sort(by_x.begin(), by_x.end(), [&](std::size_t i, std::size_t j) { return v[i].x < v[j].x || (v[i].x == v[j].x && i < j); });
  for (std::size_t i = 0; i < by_x.size(); ++i)
    for (std::size_t j = i + 1; j < by_x.size() && v[by_x[j]].x - v[by_x[i]].x < best; ++j)
      keep(std::hypot(v[by_x[j]].x - v[by_x[i]].x, v[by_x[j]].y - v[by_x[i]].y));
  for (const Segment& s : pslg.segments) {
    const Point& a = v[static_cast<std::size_t>(s.a)];
    const Point& b = v[static_cast<std::size_t>(s.b)];
    const double x0 = std::min(a.x, b.x), x1 = std::max(a.x, b.x);
    const double y0 = std::min(a.y, b.y), y1 = std::max(a.y, b.y);
    auto first = std::lower_bound(by_x.begin(), by_x.end(), x0 - best, [&](std::size_t i, double x) { return v[i].x < x; });
    for (auto it = first; it != by_x.end() && v[*it].x <= x1 + best; ++it) {
      const std::size_t i = *it;
      if (static_cast<int>(i) == s.a || static_cast<int>(i) == s.b || v[i].y < y0 - best || v[i].y > y1 + best) continue;
      keep(distance_to_segment(v[i], a, b));
    }
  }
  return best;
}

}  // namespace

double default_edge_floor(const Pslg& pslg) {
  const double feature = smallest_feature(pslg);
  if (!std::isfinite(feature)) return 0;
  return std::ldexp(feature, -20);  // a million times shorter than the input's smallest feature
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
const std::vector<Method>& all_methods() {
  static const std::vector<Method> methods = {Method::Centroid, Method::Midpoint};
  return methods;
}

bool parse_method(const std::string& name, Method& method) {
  for (Method m : all_methods())
    if (name == to_string(m)) return method = m, true;
  return false;
}

const char* to_string(QueueOrder order) {
  switch (order) {
    case QueueOrder::Fifo: return "fifo";
    case QueueOrder::Lifo: return "lifo";
    case QueueOrder::Flip: return "flip";
    case QueueOrder::Random: return "random";
    case QueueOrder::SmallestAngle: return "smallest-angle";
    case QueueOrder::Batch: return "batch";
  }
  return "?";
}

const std::vector<QueueOrder>& all_queue_orders() {
  static const std::vector<QueueOrder> orders = {QueueOrder::Fifo, QueueOrder::Lifo, QueueOrder::Flip, QueueOrder::Random,
                                                 QueueOrder::SmallestAngle, QueueOrder::Batch};
  return orders;
}

bool parse_queue_order(const std::string& name, QueueOrder& order) {
  for (QueueOrder o : all_queue_orders())
    if (name == to_string(o)) return order = o, true;
  return false;
}
const char* to_string(LeftReason reason) {
  return reason == LeftReason::SmallInputAngle ? "small-input-angle" : "double-precision";
}

int exit_status(Outcome outcome) { return outcome == Outcome::Converged ? 0 : 3; }

}  // namespace lepp
