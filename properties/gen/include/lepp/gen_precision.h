// SPDX-License-Identifier: GPL-3.0-or-later
// RapidCheck generators of inputs at the limit of double precision (issue 20):
// clusters of points a few ulps apart at a large offset, and point sets with
// near-duplicates at relative distances of 1e-12 to 1e-15, where the rounded
// Steiner point can miss the place its insertion needs (docs/ALGORITHM.md
// section 8b). Unlike gen.h these are not lattice points: the coordinates are
// doubles stepped by ulps (std::nextafter) or offset by relative amounts.
// Every PSLG has a closed box of segments, so both engines mesh it as given;
// run them through validate() first (near-duplicates may coincide exactly).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <rapidcheck.h>

#include "lepp/pslg.h"

namespace lepp::gen {

namespace detail {
// x moved by k ulps (k < 0: down).
inline double ulps(double x, int k) {
  for (; k > 0; --k) x = std::nextafter(x, HUGE_VAL);
  for (; k < 0; ++k) x = std::nextafter(x, -HUGE_VAL);
  return x;
}
inline Pslg boxed(double x0, double y0, double x1, double y1) {
  Pslg p;
  p.vertices = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  p.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 0, 1}};
  return p;
}
}  // namespace detail

/// A box [O, O + W]^2 at offset O = 2^e (e in 0..40, or O = 0) with a cluster of up
/// to 10 points, each a few ulps (-4..4 per coordinate) from a center C inside the
/// box, and up to 24 points on the diagonal through C (as the 34-point set:
/// a cluster near (0.5, 0.5) and points 0.01 to 0.96 on the unit square's diagonal).
/// With `segment`, one segment from the first cluster point to the box's corner
/// (O, O). "gen:ulp-cluster"
inline rc::Gen<Pslg> ulpCluster() {
  return rc::gen::apply(
      [](int e, int width, int cx, int cy, const std::vector<std::pair<int, int>>& steps, int diagonal, bool segment) {
        const double o = e < 0 ? 0 : std::ldexp(1.0, e), w = std::ldexp(1.0, width);
        Pslg p = detail::boxed(o, o, o + w, o + w);
        const double c_x = o + w * (1 + cx) / 18, c_y = o + w * (1 + cy) / 18;  // strictly inside
        auto add = [&](Point q) {
          for (const Point& v : p.vertices)
            if (v == q) return false;
          p.vertices.push_back(q);
          return true;
        };
        for (std::size_t i = 0; i < steps.size() && i < 10; ++i)
          add({detail::ulps(c_x, steps[i].first), detail::ulps(c_y, steps[i].second)});
        for (int k = 1; k <= diagonal; ++k) {
          const double t = 0.01 + 0.95 * k / (diagonal + 1);
          add({o + w * t, o + w * t});
        }
        if (segment && p.vertices.size() > 4) p.segments.push_back({4, 0, 2});
        p.source = "gen:ulp-cluster";
        return p;
      },
      rc::gen::inRange(-1, 41), rc::gen::inRange(-2, 4), rc::gen::inRange(0, 16), rc::gen::inRange(0, 16),
      rc::gen::container<std::vector<std::pair<int, int>>>(rc::gen::pair(rc::gen::inRange(-4, 5), rc::gen::inRange(-4, 5))),
      rc::gen::inRange(0, 25), rc::gen::arbitrary<bool>());
}

/// Up to `max_points` points in a box [O, O + W]^2 at a large offset (O = 10^3 ..
/// 10^7, W = O / 8), about a quarter of them with a near-duplicate at relative
/// distance 10^-12 to 10^-15 (relative to O) in a random direction (as Triangle's
/// greenland.node, whose coastline has nearly coincident points). "gen:near-duplicates"
inline rc::Gen<Pslg> nearDuplicates(int max_points = 60) {
  return rc::gen::apply(
      [](int decade, const std::vector<std::tuple<int, int, int, int, int>>& raw) {
        const double o = std::pow(10.0, decade), w = o / 8;
        Pslg p = detail::boxed(o, o, o + w, o + w);
        auto add = [&](Point q) {
          if (!(q.x > o && q.x < o + w && q.y > o && q.y < o + w)) return;
          for (const Point& v : p.vertices)
            if (v == q) return;
          p.vertices.push_back(q);
        };
        for (const auto& [x, y, twin, exponent, angle] : raw) {
          const Point q{o + w * (1 + x) / 1026, o + w * (1 + y) / 1026};
          add(q);
          if (twin % 4 != 0) continue;
          const double r = o * std::pow(10.0, -12 - exponent / 100.0), a = angle * (2 * M_PI / 360);
          add({q.x + r * std::cos(a), q.y + r * std::sin(a)});
        }
        p.source = "gen:near-duplicates";
        return p;
      },
      rc::gen::inRange(3, 8),
      rc::gen::resize(max_points,
                      rc::gen::container<std::vector<std::tuple<int, int, int, int, int>>>(rc::gen::tuple(
                          rc::gen::inRange(0, 1024), rc::gen::inRange(0, 1024), rc::gen::inRange(0, 4), rc::gen::inRange(0, 301),
                          rc::gen::inRange(0, 360)))));
}

/// The ulp cluster with segments inside it: up to 10 points a few ulps (-12..12 per
/// coordinate) from a center C inside a box at offset O = 2^e, joined by segments
/// between neighbours in angle around their mean (a subset of the edges of a
/// star-shaped polygon, so no two cross). Tiny constrained edges, where the
/// precision stop's rules for splits and for centroid-in-other are reached
/// (docs/ALGORITHM.md section 8b). Not in atPrecisionLimit. "gen:ulp-segments"
inline rc::Gen<Pslg> ulpClusterWithSegments() {
  return rc::gen::apply(
      [](int e, int cx, int cy, const std::vector<std::pair<int, int>>& steps, unsigned mask) {
        const double o = e < 0 ? 0 : std::ldexp(1.0, e), w = 1;
        Pslg p = detail::boxed(o, o, o + w, o + w);
        const double c_x = o + w * (1 + cx) / 18, c_y = o + w * (1 + cy) / 18;  // strictly inside
        std::vector<Point> cluster;
        for (std::size_t i = 0; i < steps.size() && i < 10; ++i) {
          const Point q{detail::ulps(c_x, steps[i].first), detail::ulps(c_y, steps[i].second)};
          if (std::find(cluster.begin(), cluster.end(), q) == cluster.end()) cluster.push_back(q);
        }
        // In angle around the mean (in ulps of C, exact enough to order a few points).
        double mx = 0, my = 0;
        for (const Point& q : cluster) mx += q.x - c_x, my += q.y - c_y;
        mx /= std::max<std::size_t>(cluster.size(), 1), my /= std::max<std::size_t>(cluster.size(), 1);
        std::sort(cluster.begin(), cluster.end(), [&](const Point& a, const Point& b) {
          return std::atan2(a.y - c_y - my, a.x - c_x - mx) < std::atan2(b.y - c_y - my, b.x - c_x - mx);
        });
        const int first = static_cast<int>(p.vertices.size()), n = static_cast<int>(cluster.size());
        p.vertices.insert(p.vertices.end(), cluster.begin(), cluster.end());
        for (int i = 0; n >= 2 && i < n; ++i)
          if ((mask >> i & 1u) && (n > 2 || i == 0)) p.segments.push_back({first + i, first + (i + 1) % n, 2});
        p.source = "gen:ulp-segments";
        return p;
      },
      rc::gen::inRange(-1, 41), rc::gen::inRange(0, 16), rc::gen::inRange(0, 16),
      rc::gen::container<std::vector<std::pair<int, int>>>(rc::gen::pair(rc::gen::inRange(-12, 13), rc::gen::inRange(-12, 13))),
      rc::gen::inRange(1u, 1024u));
}

/// A polygon with a notch thinner than an ulp: at offset X = 2^e (e in 20..60, the ulp
/// u = 2^(e - 52) there), from vertex A = (X, X) two boundary segments run nearly
/// parallel, A -> B = A + (bx, by) u and w -> A with w = A + (wx, by) u, wx > bx: the
/// outside between them is a wedge at A at most by (wx - bx) / wx ulps wide at B (a few
/// ulps, under one along much of AB), so a rounded midpoint of one of them can land
/// across the other (a split that would overlap the
/// domain beyond it: the sliver clause, docs/ALGORITHM.md section 8b). The rest of the
/// polygon is a box around A (corners at integer multiples of u, below and left of A
/// where the ulp is u / 2). Simple: the segments meet only at shared vertices. Found
/// by the 2026-12-02 notch search (corpus/regressions/precision/notch-*.poly). "gen:ulp-notch"
inline rc::Gen<Pslg> ulpNotch() {
  return rc::gen::apply(
      [](int e, int bx, int by, int dw, int top, int left, int bottom, int right) {
        const double X = std::ldexp(1.0, e), u = std::ldexp(1.0, e - 52);
        auto at = [&](int x, int y) { return Point{X + x * u, X + y * u}; };
        const int wx = bx + dw;
        Pslg p;
        // Counter-clockwise: A, B, up and around the box, back along the bottom to w.
        p.vertices = {at(0, 0), at(bx, by), at(bx, by + top), at(-left, by + top), at(-left, -bottom), at(wx + right, -bottom)};
        if (right > 0) p.vertices.push_back(at(wx + right, by));
        p.vertices.push_back(at(wx, by));
        const int n = static_cast<int>(p.vertices.size());
        for (int i = 0; i < n; ++i) p.segments.push_back({i, (i + 1) % n, 1});
        p.source = "gen:ulp-notch";
        return p;
      },
      rc::gen::inRange(20, 61), rc::gen::inRange(6, 61), rc::gen::inRange(1, 4), rc::gen::inRange(2, 81),
      rc::gen::inRange(4, 61), rc::gen::inRange(2, 41), rc::gen::inRange(2, 41), rc::gen::inRange(0, 21));
}

// Not a generator: the fixed input at the boundary of the sliver clause (ALGORITHM.md
// section 8b), shared by the engines' and the certifier's tests. At X = 2^40, u = 2^-12
// its ulp: the domain is the quadrilateral A = (X, X), B = (X + 12u, X + u),
// (X + 12u, X + 48u), (X, X + 48u) with input vertex C = (X + 6u, X + 4u) inside, so
// ABC (28.9 degrees, no input angle) is a triangle whose longest edge AB is on the
// boundary. AB's midpoint rounds (to even) to P = (X + 6u, X), half an ulp outside;
// the other rounding (X + 6u, X + u) is within the precision floor of C. Input vertex
// 3, outside the domain, at (X + 2u, X + dy): on the segment AP for dy = 0.
// Unvalidated, like the generators.
inline Pslg sliverClauseInput(double dy) {
  const double X = std::ldexp(1.0, 40), u = std::ldexp(1.0, -12);
  Pslg p;
  p.vertices = {{X, X}, {X + 12 * u, X + u}, {X + 6 * u, X + 4 * u}, {X + 2 * u, X + dy}, {X + 12 * u, X + 48 * u}, {X, X + 48 * u}};
  p.segments = {{0, 1}, {1, 4}, {4, 5}, {5, 0}};
  return p;
}

/// Either family.
inline rc::Gen<Pslg> atPrecisionLimit() { return rc::gen::oneOf(ulpCluster(), nearDuplicates()); }

}  // namespace lepp::gen
