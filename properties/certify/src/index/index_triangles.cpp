// SPDX-License-Identifier: GPL-3.0-or-later
// The mesh index's first pass, one visit per triangle: valid ids, orientation, the longest
// edge, the corners with an angle below theta (the minimum-angle check's candidates), the
// largest angle over 120 degrees (Theorem 2's) and, with one area bound, the triangles
// above it (the size-bound check's). One pass and not five: each loaded the triangle's
// three points, and at 10^7 triangles those loads, not the arithmetic, were much of each
// pass's time.
#include <array>
#include <cmath>

#include "../exact.h"
#include "../prefetch.h"
#include "../passes.h"
#include "../ranges.h"
#include "lepp/angle.h"

namespace lepp::certify::pass {
namespace {

using exact::ErrorBounded;

// The index i of the longest half-edge of valid triangle t (half-edge i runs x[i] -> x[i + 1])
// in the edge order (ALGORITHM.md section 3), from the sides' squared lengths with their
// error bounds: their difference is the first filter of compare_squared_length, step for step.
int longest_side(const MeshIndex& ix, std::size_t t, const std::array<ErrorBounded, 3>& length) {
  int best = 0;
  for (int i = 1; i < 3; ++i) {
    const int h = static_cast<int>(3 * t) + i, b = static_cast<int>(3 * t) + best;
    const int s = (length[static_cast<std::size_t>(i)] - length[static_cast<std::size_t>(best)]).sign_or_undecided();
    if (s == 2 || s == 0 ? ix.longer(ix.from(h), ix.to(h), ix.from(b), ix.to(b)) : s > 0) best = i;  // a tie: by ids
  }
  return best;
}

}  // namespace

void index_triangles(Certification& cert) {
  MeshIndex& ix = cert.index;
  const int n = static_cast<int>(ix.mesh.vertices.size());
  const std::size_t nt = ix.mesh.triangles.size();
  ix.tri_ok.assign(nt, 0);
  ix.ccw.assign(nt, 0);
  ix.longest.assign(nt, 0);
  const bool theorem2 = cert.options.theorem2;
  ix.largest_over_120.assign(theorem2 ? nt : 0, 0);
  // The minimum-angle check's search (docs/CERTIFIER.md section 5): sin^2 theta's bracket.
  const bool angles = cert.options.min_angle_deg > 0;
  const Sin2Bracket bracket = sin2_bracket(angles ? cert.options.min_angle_deg : 30);
  // The corner facing the longest edge has the largest angle, at least 60 degrees: when
  // sin^2 theta's upper bracket is below sin^2 60 = 3/4, that corner is never below
  // theta (an obtuse one is not acute) and is not tested.
  const bool skip_largest = bracket.hi < 0.75;
  ix.below_theta.assign(range_count(cert, nt), {});
  // The size-bound check's areas (section 7) where one bound holds everywhere (--max-area
  // without region bounds); region bounds wait for the regions' flooding.
  const bool one_bound = cert.options.max_area > 0 && std::isfinite(cert.options.max_area) && !cert.options.region_area_bounds;
  const double area_limit = ix.area_bound.bound = one_bound ? cert.options.max_area : 0;
  ix.area_bound.above.assign(range_count(cert, nt), {});
  over_ranges(cert, nt, [&](std::size_t begin, std::size_t end, RangeFindings& found) {
    std::vector<MeshIndex::BelowTheta>& below = ix.below_theta[found.range];
    std::vector<std::size_t>& above = ix.area_bound.above[found.range];
    for (std::size_t t = begin; t < end; ++t) {
      if (t + kAhead < end) prefetch_points(ix, ix.T(t + kAhead));
      const Tri& x = ix.T(t);
      bool ids = true;
      for (int v : x) ids = ids && v >= 0 && v < n;
      if (!ids || x[0] == x[1] || x[1] == x[2] || x[0] == x[2]) {
        found.add({Reason::BadTriangle, fmt::format("triangle {} has vertex ids {} {} {} (out of range or repeated)", t, x[0], x[1], x[2]),
                   {static_cast<int>(t)}, {}, {}, {}, -1});
        continue;
      }
      const Point &a = ix.P(x[0]), &b = ix.P(x[1]), &c = ix.P(x[2]);
      if (!finite(a) || !finite(b) || !finite(c)) {
        found.add({Reason::BadTriangle, fmt::format("{} has a NaN or infinite coordinate", ix.tri_text(t)), {static_cast<int>(t)}, {}, {}, {}, -1});
        continue;
      }
      ix.tri_ok[t] = 1;  // ranges write apart
      const bool ccw = exact::orient(a, b, c) > 0;
      if (ccw)
        ix.ccw[t] = 1;
      else
        found.add({Reason::NotCounterClockwise, fmt::format("{} is not strictly counter-clockwise", ix.tri_text(t)),
                   {static_cast<int>(t)}, {}, {x[0], x[1], x[2]}, {}, -1});
      // The longest edge, the area against one bound and the small corners' sine tests
      // through one first filter (exact.h).
      const exact::TriangleShape shape(a, b, c);
      const int longest = longest_side(ix, t, shape.squared_lengths());
      ix.longest[t] = static_cast<signed char>(longest);
      if (area_limit > 0 && shape.doubled_area_above(area_limit)) above.push_back(t);
      if (theorem2) ix.largest_over_120[t] = shape.angle_over_120_at((longest + 2) % 3);  // ranges write apart
      if (!angles) continue;
      // A corner with an angle below theta (the smallest such angle is not needed):
      // the first below the upper bracket, unless a later one is certainly below.
      int worst = -1;
      bool certainly = false;
      auto corner = [&](int i, bool below_hi, auto&& below_lo) {
        if (below_hi) {
          const bool below = below_lo();
          if (worst < 0 || (below && !certainly)) {
            worst = i;
            certainly = below;
          }
        }
      };
      const int largest = skip_largest ? (longest + 2) % 3 : -1;  // the corner facing the longest edge
      if (largest >= 0 && ccw) {
        for (int i = 0; i < 3; ++i)
          if (i != largest) corner(i, shape.sin2_below(i, bracket.hi), [&] { return shape.sin2_below(i, bracket.lo); });
      } else {  // all three corners, or a clockwise or degenerate triangle: each corner on its own
        for (int i = 0; i < 3; ++i) {
          if (i == largest) continue;
          const Point &o = ix.P(x[static_cast<std::size_t>(i)]), &p = ix.P(x[static_cast<std::size_t>((i + 1) % 3)]),
                      &q = ix.P(x[static_cast<std::size_t>((i + 2) % 3)]);
          corner(i, exact::acute_angle_sin2_below(o, p, q, bracket.hi), [&] { return exact::acute_angle_sin2_below(o, p, q, bracket.lo); });
        }
      }
      if (worst >= 0) below.push_back({t, worst, certainly});
    }
  });
}

}  // namespace lepp::certify::pass
