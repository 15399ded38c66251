// SPDX-License-Identifier: GPL-3.0-or-later
// PSLGs in general position for impl's properties: a star-shaped simple polygon
// (random angles and radii around the origin) as the boundary, random points
// in its box, sometimes a crack (an interior segment). Coordinates come from
// integers in [0, 2^20) scaled: readable when shrunk, and four cocircular points
// are rare. Replaced by properties/gen when that lands.
#pragma once
#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include <rapidcheck.h>

#include "lepp/pslg.h"
#include "lepp/validate.h"

namespace lepp::impl_test {

struct RawPslg {
  std::vector<int> angles;                  // boundary vertex angles, in 1/4096 of a turn
  std::vector<int> radii;                   // in [2^19, 2^20)
  std::vector<std::pair<int, int>> points;  // in [0, 2^20)^2, mapped to [-1, 1]^2
  bool crack = false;                       // a segment between the first two points
};

inline double unit(int k) { return std::ldexp(static_cast<double>(k), -19) - 1.0; }

// The PSLG, validated; empty (no vertices) when validation rejects it.
inline Pslg to_pslg(const RawPslg& raw) {
  Pslg p;
  std::set<int> angles(raw.angles.begin(), raw.angles.end());
  std::size_t k = 0;
  for (int a : angles) {
    double r = std::ldexp(static_cast<double>(raw.radii[k++ % raw.radii.size()]), -20);
    double t = 2 * M_PI * a / 4096.0;
    p.vertices.push_back({r * std::cos(t), r * std::sin(t)});
  }
  int nb = static_cast<int>(p.vertices.size());
  if (nb < 3) return {};
  for (int i = 0; i < nb; ++i) p.segments.push_back({i, (i + 1) % nb, 1});
  for (auto [x, y] : raw.points) p.vertices.push_back({unit(x), unit(y)});
  if (raw.crack && raw.points.size() >= 2) p.segments.push_back({nb, nb + 1, 0});
  try {
    std::vector<std::string> warnings;
    return validate(p, warnings);
  } catch (const std::exception&) {
    return {};
  }
}

inline rc::Gen<RawPslg> gen_raw_pslg(int max_boundary = 24, int max_points = 24) {
  return rc::gen::build<RawPslg>(
      rc::gen::set(&RawPslg::angles,
                   rc::gen::suchThat(rc::gen::resize(max_boundary, rc::gen::container<std::vector<int>>(
                                                                      rc::gen::inRange(0, 4096))),
                                     [](const std::vector<int>& v) { return v.size() >= 3; })),
      rc::gen::set(&RawPslg::radii,
                   rc::gen::nonEmpty(rc::gen::container<std::vector<int>>(rc::gen::inRange(1 << 19, 1 << 20)))),
      rc::gen::set(&RawPslg::points,
                   rc::gen::resize(max_points, rc::gen::container<std::vector<std::pair<int, int>>>(rc::gen::pair(
                                                   rc::gen::inRange(0, 1 << 20), rc::gen::inRange(0, 1 << 20))))),
      rc::gen::set(&RawPslg::crack, rc::gen::arbitrary<bool>()));
}

}  // namespace lepp::impl_test
