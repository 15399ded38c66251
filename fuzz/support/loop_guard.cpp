// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind loop_guard.h: what counts as a loop in a fuzzed refinement, and what
// kind of loop it is.
#include "loop_guard.h"

#include "lepp/segment_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

namespace lepp::fuzz {

namespace {

double angle_deg(const Point& v, const Point& a, const Point& b) {
  const double ux = a.x - v.x, uy = a.y - v.y, wx = b.x - v.x, wy = b.y - v.y;
  return std::atan2(std::fabs(ux * wy - uy * wx), ux * wx + uy * wy) * 180.0 / M_PI;
}

// Smallest angle between segments meeting at v (180 if fewer than two).
double angle_at(const Pslg& pslg, int v) {
  std::vector<int> others;
  for (const Segment& s : pslg.segments) {
    if (s.a == v) others.push_back(s.b);
    if (s.b == v) others.push_back(s.a);
  }
  double best = 180;
  const Point& pv = pslg.vertices[static_cast<std::size_t>(v)];
  for (std::size_t i = 0; i < others.size(); ++i)
    for (std::size_t j = i + 1; j < others.size(); ++j)
      best = std::min(best, angle_deg(pv, pslg.vertices[static_cast<std::size_t>(others[i])],
                                      pslg.vertices[static_cast<std::size_t>(others[j])]));
  return best;
}

double tri_angle_min(const Point& a, const Point& b, const Point& c, double* second) {
  double angles[3] = {angle_deg(a, b, c), angle_deg(b, c, a), angle_deg(c, a, b)};
  std::sort(angles, angles + 3);
  *second = angles[1];
  return angles[0];
}

}  // namespace

InputFeatures input_features(const Pslg& pslg) {
  InputFeatures f;
  double lfs = std::numeric_limits<double>::infinity();
  const auto& v = pslg.vertices;
  for (std::size_t i = 0; i < v.size(); ++i)
    for (std::size_t j = i + 1; j < v.size(); ++j) lfs = std::min(lfs, std::hypot(v[i].x - v[j].x, v[i].y - v[j].y));
  for (const Segment& s : pslg.segments)
    for (std::size_t i = 0; i < v.size(); ++i)
      if (static_cast<int>(i) != s.a && static_cast<int>(i) != s.b)
        lfs = std::min(lfs, distance_to_segment(v[i], v[static_cast<std::size_t>(s.a)], v[static_cast<std::size_t>(s.b)]));
  f.lfs_min = lfs;
  double x0 = v[0].x, x1 = x0, y0 = v[0].y, y1 = y0;
  for (const Point& p : v) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  f.bbox_area = (x1 - x0) * (y1 - y0);
  for (std::size_t i = 0; i < v.size(); ++i) f.min_input_angle_deg = std::min(f.min_input_angle_deg, angle_at(pslg, static_cast<int>(i)));
  return f;
}

LoopGuard loop_guard(const Pslg& pslg, std::int64_t cap) {
  const InputFeatures f = input_features(pslg);
  const double n = static_cast<double>(pslg.vertices.size() + pslg.segments.size());
  const double budget = 64 * n + 16 * f.bbox_area / (f.lfs_min * f.lfs_min);
  LoopGuard g;
  g.steiner_budget = static_cast<std::int64_t>(std::min(budget, static_cast<double>(cap)));
  g.edge_floor = std::ldexp(f.lfs_min, -10);
  return g;
}

double alpha_limit_deg() {
  return std::atan((std::sqrt(15.0) - std::sqrt(3.0)) / (3 + std::sqrt(5.0))) * 180.0 / M_PI;
}

std::string classify_loop(const Pslg& pslg, const RefineOptions& options, const RefineResult& traced) {
  const Mesh& m = traced.mesh;
  // Where is the shortest edge? Near an input vertex with a small angle: cascade.
  double shortest = std::numeric_limits<double>::infinity();
  Point at{};
  for (const Tri& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      const Point &a = m.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])],
                  &b = m.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>((k + 1) % 3)])];
      const double d = std::hypot(a.x - b.x, a.y - b.y);
      if (d < shortest) shortest = d, at = {(a.x + b.x) / 2, (a.y + b.y) / 2};
    }
  if (std::isfinite(shortest)) {
    int nearest = 0;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < pslg.vertices.size(); ++i) {
      const double d = std::hypot(pslg.vertices[i].x - at.x, pslg.vertices[i].y - at.y);
      if (d < best) best = d, nearest = static_cast<int>(i);
    }
    if (angle_at(pslg, nearest) < 60 && best < 0.25 * input_features(pslg).lfs_min) return "small-angle-cascade";
  }
  // Self-similar repetition among the last bad triangles processed.
  std::map<std::pair<long long, long long>, std::vector<double>> sizes_by_shape;
  const std::size_t tail = std::min<std::size_t>(traced.trace.size(), 256);
  for (std::size_t i = traced.trace.size() - tail; i < traced.trace.size(); ++i) {
    const Tri& t = traced.trace[i].bad;
    const Point &a = m.vertices[static_cast<std::size_t>(t[0])], &b = m.vertices[static_cast<std::size_t>(t[1])],
                &c = m.vertices[static_cast<std::size_t>(t[2])];
    double second = 0;
    const double first = tri_angle_min(a, b, c, &second);
    const double size = std::max({std::hypot(a.x - b.x, a.y - b.y), std::hypot(b.x - c.x, b.y - c.y), std::hypot(c.x - a.x, c.y - a.y)});
    sizes_by_shape[{std::llround(first * 1e6), std::llround(second * 1e6)}].push_back(size);
  }
  bool self_similar = false;
  for (const auto& [shape, sizes] : sizes_by_shape) {
    if (sizes.size() < 4) continue;
    int shrinking = 0;
    for (std::size_t i = 1; i < sizes.size(); ++i) shrinking += sizes[i] < sizes[i - 1];
    self_similar = self_similar || shrinking >= 3;
  }
  if (self_similar)
    return options.method == Method::Midpoint && options.min_angle_deg > alpha_limit_deg() ? "midpoint-special-loop"
                                                                                          : "self-similar-loop";
  return "other";
}

const char* theta_band(double theta) {
  if (theta <= 20.7) return "<=20.7";
  if (theta <= 22.2) return "<=22.2";
  if (theta <= 30) return "<=30";
  return "<=36";
}

}  // namespace lepp::fuzz
