// SPDX-License-Identifier: GPL-3.0-or-later
#include "lepp/stats.h"

#include "lepp/refine.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lepp {

double average_lepp_size(const RefineResult& result) {
  return result.lepp_searches ? static_cast<double>(result.lepp_triangles) / static_cast<double>(result.lepp_searches) : 0;
}

namespace {
double len(const Point& a, const Point& b) { return std::hypot(a.x - b.x, a.y - b.y); }

// p - o scaled by a power of two so that its larger component is in [1, 2): the
// direction is kept and neither the difference nor the products after it over- or
// underflow. A difference that overflows is taken of the halves (exact at that size).
Point scaled_direction(const Point& o, const Point& p) {
  double dx = p.x - o.x, dy = p.y - o.y;
  if (!std::isfinite(dx) || !std::isfinite(dy)) dx = p.x / 2 - o.x / 2, dy = p.y / 2 - o.y / 2;
  const double m = std::max(std::abs(dx), std::abs(dy));
  if (!(m > 0) || !std::isfinite(m)) return {dx, dy};
  const int e = std::ilogb(m);
  return {std::ldexp(dx, -e), std::ldexp(dy, -e)};
}
}  // namespace

double signed_angle_deg(const Point& o, const Point& p, const Point& q) {
  const Point u = scaled_direction(o, p), v = scaled_direction(o, q);
  return std::atan2(u.x * v.y - u.y * v.x, u.x * v.x + u.y * v.y) * 180.0 / M_PI;
}

double angle_deg(const Point& o, const Point& p, const Point& q) { return std::abs(signed_angle_deg(o, p, q)); }

double min_angle_deg(const Point& a, const Point& b, const Point& c) {
  return std::min({angle_deg(a, b, c), angle_deg(b, c, a), angle_deg(c, a, b)});
}

double max_angle_deg(const Point& a, const Point& b, const Point& c) {
  return std::max({angle_deg(a, b, c), angle_deg(b, c, a), angle_deg(c, a, b)});
}

double radius_ratio(const Point& a, const Point& b, const Point& c) {
  // 2 r / R = 16 area^2 / (|ab| |bc| |ca| (|ab| + |bc| + |ca|)).
  const double area2 = std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  const double ab = len(a, b), bc = len(b, c), ca = len(c, a);
  const double den = ab * bc * ca * (ab + bc + ca);
  return den > 0 ? 4.0 * area2 * area2 / den : 0.0;
}

double edge_ratio(const Point& a, const Point& b, const Point& c) {
  const double ab = len(a, b), bc = len(b, c), ca = len(c, a);
  const double lo = std::min({ab, bc, ca});
  return lo > 0 ? std::max({ab, bc, ca}) / lo : std::numeric_limits<double>::infinity();
}

double area_quality(const Point& a, const Point& b, const Point& c) {
  double area2 = std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  double l = std::max({len(a, b), len(b, c), len(c, a)});
  return l > 0 ? (2.0 / std::sqrt(3.0)) * area2 / (l * l) : 0.0;
}

MeshStats mesh_stats(const Mesh& mesh, const Pslg& input) {
  MeshStats s;
  s.vertices = mesh.vertices.size();
  s.triangles = mesh.triangles.size();
  double min_angle = 180, sum = 0, min_q = std::numeric_limits<double>::infinity();
  double shortest = std::numeric_limits<double>::infinity();
  for (const Tri& t : mesh.triangles) {
    const Point &a = mesh.vertices[static_cast<std::size_t>(t[0])], &b = mesh.vertices[static_cast<std::size_t>(t[1])],
                &c = mesh.vertices[static_cast<std::size_t>(t[2])];
    double m = min_angle_deg(a, b, c);
    min_angle = std::min(min_angle, m);
    sum += m;
    min_q = std::min(min_q, area_quality(a, b, c));
    shortest = std::min({shortest, len(a, b), len(b, c), len(c, a)});
  }
  double input_shortest = std::numeric_limits<double>::infinity();
  for (const Segment& seg : input.segments)
    input_shortest = std::min(input_shortest, len(input.vertices[static_cast<std::size_t>(seg.a)],
                                                  input.vertices[static_cast<std::size_t>(seg.b)]));
  if (!mesh.triangles.empty()) {
    s.min_angle_deg = min_angle;
    s.avg_min_angle_deg = sum / static_cast<double>(mesh.triangles.size());
    s.min_area_quality = min_q;
    s.shortest_edge = shortest;
    s.shortest_edge_ratio = std::isfinite(input_shortest) && input_shortest > 0 ? shortest / input_shortest : 0;
  }
  return s;
}

}  // namespace lepp
