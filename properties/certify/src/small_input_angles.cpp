// SPDX-License-Identifier: GPL-3.0-or-later
// The small input angles of a PSLG, from the input alone (docs/CERTIFIER.md).
#include "lepp/small_input_angles.h"

#include <algorithm>
#include <cmath>

#include "exact.h"
#include "lepp/stats.h"
#include "expected_domain.h"
#include "small_input_angles_internal.h"

namespace lepp::certify {
namespace {

// The upper half-plane of directions (angle in [0, 180)) comes first around apex.
bool upper(const Point& v, const Point& u) { return u.y > v.y || (u.y == v.y && u.x > v.x); }

// The wedge from v->u counter-clockwise to v->w is below 60 degrees, exactly.
bool below_60(const Point& v, const Point& u, const Point& w) {
  if (exact::orient(v, u, w) <= 0 || exact::sign_dot(v, u, w) <= 0) return false;
  return exact::sign([&](auto z) -> decltype(z) {
           using NT = decltype(z);
           NT ux = NT(u.x) - NT(v.x), uy = NT(u.y) - NT(v.y), wx = NT(w.x) - NT(v.x), wy = NT(w.y) - NT(v.y);
           NT cross = ux * wy - uy * wx;
           return NT(4) * cross * cross - NT(3) * (ux * ux + uy * uy) * (wx * wx + wy * wy);
         }) < 0;
}

}  // namespace

std::vector<SmallInputAngle> small_input_angles(const Pslg& pslg, const ExpectedDomain& domain) {
  const std::size_t n = pslg.vertices.size();
  std::vector<std::vector<int>> incident(n);
  for (std::size_t s = 0; s < pslg.segments.size(); ++s) {
    incident[static_cast<std::size_t>(pslg.segments[s].a)].push_back(static_cast<int>(s));
    incident[static_cast<std::size_t>(pslg.segments[s].b)].push_back(static_cast<int>(s));
  }
  std::vector<SmallInputAngle> out;
  for (std::size_t vi = 0; vi < n; ++vi) {
    std::vector<int>& around = incident[vi];
    if (around.size() < 2) continue;
    const Point& V = pslg.vertices[vi];
    auto other = [&](int s) {
      const Segment& g = pslg.segments[static_cast<std::size_t>(s)];
      return g.a == static_cast<int>(vi) ? g.b : g.a;
    };
    auto P = [&](int id) -> const Point& { return pslg.vertices[static_cast<std::size_t>(id)]; };
    // Counter-clockwise order of the segments around the apex (exact: half-plane, then orientation).
    std::sort(around.begin(), around.end(), [&](int s, int t) {
      const Point &U = P(other(s)), &W = P(other(t));
      const bool us = upper(V, U), ws = upper(V, W);
      if (us != ws) return us;
      return exact::orient(V, U, W) > 0;
    });
    // The wedge after segment around[i] (counter-clockwise, up to the next segment) is
    // domain iff the left side of the ray apex -> other end is: the left side of the
    // segment when the apex is its first endpoint, its right side otherwise.
    auto wedge_in_domain = [&](int s) {
      const Segment& g = pslg.segments[static_cast<std::size_t>(s)];
      const unsigned char side = g.a == static_cast<int>(vi) ? ExpectedDomain::Left : ExpectedDomain::Right;
      return (domain.segment_sides[static_cast<std::size_t>(s)] & side) != 0;
    };
    const std::size_t k = around.size();
    for (std::size_t i = 0; i < k; ++i) {
      // Every pair (around[i], around[j]) whose whole wedge is domain and below 60 degrees:
      // adjacent segments, and segments a cluster of small angles apart.
      for (std::size_t step = 1; step < k; ++step) {
        const int s1 = around[i], s2 = around[(i + step) % k], last = around[(i + step - 1) % k];
        if (!wedge_in_domain(last)) break;
        const int e1 = other(s1), e2 = other(s2);
        if (!below_60(V, P(e1), P(e2))) break;
        SmallInputAngle a;
        a.apex = static_cast<int>(vi);
        a.segment1 = s1;
        a.segment2 = s2;
        a.end1 = e1;
        a.end2 = e2;
        a.near_end = exact::compare_squared_length(V, P(e2), V, P(e1)) < 0 ? e2 : e1;
        a.angle_deg = signed_angle_deg(V, P(e1), P(e2));  // scaled: right at any magnitude
        a.radius = std::hypot(P(a.near_end).x - V.x, P(a.near_end).y - V.y);
        out.push_back(a);
      }
    }
  }
  return out;
}

std::vector<SmallInputAngle> small_input_angles(const Pslg& validated) {
  return small_input_angles(validated, expected_domain(validated));
}

}  // namespace lepp::certify
