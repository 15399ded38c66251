// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind problems.h: benchmark inputs.
#include "problems.h"

#include <cmath>
#include <random>

#include <fmt/format.h>

#include "lepp/io.h"
#include "lepp/validate.h"

namespace lepp::bench {
namespace {

// The unit square's boundary with m vertices per side, counter-clockwise.
Pslg square_boundary(int m) {
  Pslg p;
  for (int side = 0; side < 4; ++side) {
    for (int i = 0; i < m; ++i) {
      double t = static_cast<double>(i) / m;
      Point q = side == 0 ? Point{t, 0} : side == 1 ? Point{1, t} : side == 2 ? Point{1 - t, 1} : Point{0, 1 - t};
      p.vertices.push_back(q);
    }
  }
  int n = static_cast<int>(p.vertices.size());
  for (int i = 0; i < n; ++i) p.segments.push_back({i, (i + 1) % n, 1});
  return p;
}

Pslg validated(const Pslg& p) {
  std::vector<std::string> warnings;
  return validate(p, warnings);
}

}  // namespace

RefineOptions refine_options(const Problem& p) {
  RefineOptions o;
  o.min_angle_deg = p.theta;
  o.max_area = p.max_area;
  return o;
}

std::vector<Problem> paper_problems(const std::string& corpus_dir, double theta) {
  std::vector<Problem> out;
  for (const char* name : {"A", "square400", "circles240", "rect162"}) {
    std::vector<std::string> warnings;
    out.push_back({name, validate(read_poly(corpus_dir + "/" + name + ".poly"), warnings), theta, 0});
  }
  return out;
}

Problem square_with_size_bound(double triangles) {
  Problem p;
  int m = std::max(8, static_cast<int>(std::sqrt(triangles) / 1.5));
  p.pslg = validated(square_boundary(m));
  p.max_area = 1.4 / triangles;
  p.name = fmt::format("square_1e{}", static_cast<int>(std::lround(std::log10(triangles))));
  return p;
}

Problem random_points(int count) {
  Problem p;
  Pslg s = square_boundary(64);
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> u(0.001, 0.999);
  for (int i = 0; i < count; ++i) s.vertices.push_back({u(rng), u(rng)});
  p.pslg = validated(s);
  p.name = fmt::format("random_points_{}", count);
  return p;
}

}  // namespace lepp::bench
