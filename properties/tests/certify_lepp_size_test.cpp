// SPDX-License-Identifier: GPL-3.0-or-later
// The statistics' mean Lepp size (Report::stats.avg_lepp_size) on meshes whose Lepps are
// long and known in closed form: fans around a point whose longest edges chain, so that
// triangle k's Lepp runs through every later triangle. The certifier remembers the sizes
// of long walks (statistics.cpp); these sums say it remembers them right, for one range
// and for several (threads), with the walk ending on the boundary and on a terminal pair.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "lepp/certify.h"
#include "lepp/mesh.h"
#include "lepp/pslg.h"

namespace lepp {
namespace {

// Fan points P_0..P_n around O = (0, 0): radii 1000 + 4k (rounded to integers, so
// |OP_k| still grows by more than 2 each step), angles from -1.2 up to 0 radians. The
// triangle (O, P_k, P_{k+1}) has O-P_{k+1} as its longest edge, shared with the next.
std::vector<Point> fan_points(int n) {
  std::vector<Point> p;
  for (int k = 0; k <= n; ++k) {
    const double r = 1000 + 4.0 * k, a = -1.2 * (n - k) / n;
    p.push_back({std::round(r * std::cos(a)), std::round(r * std::sin(a))});
  }
  return p;
}

double mean_lepp_size(const Pslg& pslg, const Mesh& mesh, int threads) {
  certify::Options options;
  options.threads = threads;
  return certify::certify(pslg, mesh, options).stats.avg_lepp_size;
}

// One fan, O-P_n on the boundary: triangle k's Lepp is triangles k..n-1, n - k of them,
// so the mean is (n + 1) / 2.
TEST(CertifyLeppSize, AFanEndingOnTheBoundary) {
  const int n = 200;
  Pslg pslg;
  pslg.vertices = {{0, 0}};
  for (const Point& q : fan_points(n)) pslg.vertices.push_back(q);
  Mesh mesh;
  mesh.vertices = pslg.vertices;
  mesh.input_vertices = static_cast<int>(pslg.vertices.size());
  for (int k = 0; k < n; ++k) mesh.triangles.push_back({0, k + 1, k + 2});
  for (int v = 0; v <= n + 1; ++v) pslg.segments.push_back({v, (v + 1) % (n + 2)});  // O, P_0, ..., P_n
  for (int threads : {1, 2, 3}) EXPECT_EQ(mean_lepp_size(pslg, mesh, threads), (n + 1) / 2.0) << threads;
}

// Two fans mirrored across the x axis, meeting on O-P_n, the longest edge of both last
// triangles: a terminal pair. Triangle k of either fan has the n - k triangles of its
// own fan and the other fan's last one, so the mean over 2n triangles is (n + 3) / 2.
TEST(CertifyLeppSize, TwoFansMeetingOnATerminalPair) {
  const int n = 200;
  const std::vector<Point> p = fan_points(n);
  Pslg pslg;
  pslg.vertices = {{0, 0}};
  for (const Point& q : p) pslg.vertices.push_back(q);                                    // P_k: 1 + k
  for (int k = 0; k < n; ++k) pslg.vertices.push_back({p[static_cast<std::size_t>(k)].x, -p[static_cast<std::size_t>(k)].y});  // Q_k: n + 2 + k
  auto P = [](int k) { return 1 + k; };
  auto Q = [&](int k) { return k == n ? P(n) : n + 2 + k; };
  Mesh mesh;
  mesh.vertices = pslg.vertices;
  mesh.input_vertices = static_cast<int>(pslg.vertices.size());
  for (int k = 0; k < n; ++k) mesh.triangles.push_back({0, P(k), P(k + 1)});
  for (int k = 0; k < n; ++k) mesh.triangles.push_back({0, Q(k + 1), Q(k)});
  pslg.segments.push_back({0, P(0)});
  pslg.segments.push_back({0, Q(0)});
  for (int k = 0; k < n; ++k) {
    pslg.segments.push_back({P(k), P(k + 1)});
    pslg.segments.push_back({Q(k), Q(k + 1)});
  }
  for (int threads : {1, 2, 3}) EXPECT_EQ(mean_lepp_size(pslg, mesh, threads), (n + 3) / 2.0) << threads;
}

}  // namespace
}  // namespace lepp
