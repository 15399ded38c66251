// SPDX-License-Identifier: GPL-3.0-or-later
// RapidCheck generators of PSLGs, triangles and Delaunay terminal pairs, for
// property tests here and in other projects (find_package(lepp): lepp::gen).
//
// Every coordinate is an integer (a double holding a small integer, |x| < 2^12)
// multiplied by `scale` (a power of two, default 1): sums, differences and the
// predicates of degree <= 4 on them are exact in double, so a counterexample is
// small, readable and means what it says. Every generated PSLG passes
// lepp::validate (no crossings, no duplicates, no vertex inside a segment; a
// property in properties/tests checks it). Pslg::source names the family
// ("gen:convex", ...) so properties can RC_CLASSIFY by it.
//
// All generators shrink: toward fewer vertices, smaller coordinates, coarser sampling.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <rapidcheck.h>

#include "lepp/pslg.h"
#include "lepp/stats.h"

namespace lepp::gen {

// A lattice point of the grid the generators draw on.
struct IPoint {
  std::int64_t x = 0, y = 0;
  friend bool operator==(const IPoint& a, const IPoint& b) { return a.x == b.x && a.y == b.y; }
  friend bool operator<(const IPoint& a, const IPoint& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }
};

namespace detail {

inline std::int64_t cross(const IPoint& o, const IPoint& a, const IPoint& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}
inline std::int64_t dot(const IPoint& o, const IPoint& a, const IPoint& b) {
  return (a.x - o.x) * (b.x - o.x) + (a.y - o.y) * (b.y - o.y);
}
// p on the closed segment ab
inline bool on_segment(const IPoint& a, const IPoint& b, const IPoint& p) {
  return cross(a, b, p) == 0 && dot(p, a, b) <= 0;
}
// Closed segments ab and cd share a point.
inline bool segments_touch(const IPoint& a, const IPoint& b, const IPoint& c, const IPoint& d) {
  const std::int64_t d1 = cross(a, b, c), d2 = cross(a, b, d), d3 = cross(c, d, a), d4 = cross(c, d, b);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  return on_segment(a, b, c) || on_segment(a, b, d) || on_segment(c, d, a) || on_segment(c, d, b);
}

// Builds a Pslg on the lattice: vertices are deduplicated; a segment is split at
// every vertex already on it when added (callers add vertices before segments).
class Builder {
 public:
  int vertex(IPoint p) {
    for (std::size_t i = 0; i < points_.size(); ++i)
      if (points_[i] == p) return static_cast<int>(i);
    points_.push_back(p);
    return static_cast<int>(points_.size()) - 1;
  }
  // A closed polygon, each edge sampled at every `stride`-th lattice point on it.
  void ring(const std::vector<IPoint>& corners, std::int64_t stride, int marker) {
    std::vector<int> ids;
    for (std::size_t i = 0; i < corners.size(); ++i) {
      const IPoint a = corners[i], b = corners[(i + 1) % corners.size()];
      ids.push_back(vertex(a));
      for (const IPoint& p : lattice_points(a, b, stride)) ids.push_back(vertex(p));
    }
    for (std::size_t i = 0; i < ids.size(); ++i) segments_.push_back({ids[i], ids[(i + 1) % ids.size()], marker});
  }
  // An open segment ab, sampled like ring().
  void path(IPoint a, IPoint b, std::int64_t stride, int marker) {
    std::vector<int> ids{vertex(a)};
    for (const IPoint& p : lattice_points(a, b, stride)) ids.push_back(vertex(p));
    ids.push_back(vertex(b));
    for (std::size_t i = 0; i + 1 < ids.size(); ++i) segments_.push_back({ids[i], ids[i + 1], marker});
  }
  void hole(IPoint p) { holes_.push_back(p); }
  // Is p a vertex or on a segment already?
  bool occupied(IPoint p) const {
    for (const IPoint& q : points_)
      if (q == p) return true;
    for (const Segment& s : segments_)
      if (on_segment(points_[static_cast<std::size_t>(s.a)], points_[static_cast<std::size_t>(s.b)], p)) return true;
    return false;
  }
  // Would segment ab touch an existing vertex or segment (other than at nothing)?
  bool blocked(IPoint a, IPoint b) const {
    if (a == b) return true;
    for (const IPoint& q : points_)
      if (on_segment(a, b, q)) return true;
    for (const Segment& s : segments_)
      if (segments_touch(a, b, points_[static_cast<std::size_t>(s.a)], points_[static_cast<std::size_t>(s.b)])) return true;
    return false;
  }
  Pslg build(const char* family, double scale) const {
    Pslg p;
    for (const IPoint& q : points_) p.vertices.push_back({static_cast<double>(q.x) * scale, static_cast<double>(q.y) * scale});
    p.segments = segments_;
    for (const IPoint& h : holes_) p.holes.push_back({static_cast<double>(h.x) * scale, static_cast<double>(h.y) * scale});
    p.source = family;
    return p;
  }

  static std::vector<IPoint> lattice_points(IPoint a, IPoint b, std::int64_t stride) {
    const std::int64_t dx = b.x - a.x, dy = b.y - a.y;
    const std::int64_t g = std::gcd(dx < 0 ? -dx : dx, dy < 0 ? -dy : dy);
    std::vector<IPoint> out;
    if (g == 0 || stride <= 0) return out;
    for (std::int64_t k = stride; k < g; k += stride) out.push_back({a.x + k * (dx / g), a.y + k * (dy / g)});
    return out;
  }

 private:
  std::vector<IPoint> points_;
  std::vector<Segment> segments_;
  std::vector<IPoint> holes_;
};

// Convex hull (counter-clockwise, no collinear points), Andrew's monotone chain, exact.
inline std::vector<IPoint> convex_hull(std::vector<IPoint> pts) {
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 3) return pts;
  std::vector<IPoint> h(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
    h[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
    h[k++] = pts[i];
  }
  h.resize(k - 1);
  return h;
}

// A polygon star-shaped around the origin: vertex i at angle (i + jitter_i/100) * 360/n
// and radius r_i, rounded to the lattice. Simple by construction when the rounded
// vertices stay in angular order with every turn around the origin below 180
// degrees; otherwise (never for the ranges used here) the regular polygon.
inline std::vector<IPoint> star(const std::vector<std::pair<int, int>>& jitter_radius, std::int64_t regular_radius) {
  const std::size_t n = jitter_radius.size();
  auto make = [&](bool jittered) {
    std::vector<IPoint> v;
    for (std::size_t i = 0; i < n; ++i) {
      const double a = (static_cast<double>(i) + (jittered ? jitter_radius[i].first / 100.0 : 0)) * 2 * M_PI / static_cast<double>(n);
      const double r = jittered ? jitter_radius[i].second : static_cast<double>(regular_radius);
      v.push_back({static_cast<std::int64_t>(std::lround(r * std::cos(a))), static_cast<std::int64_t>(std::lround(r * std::sin(a)))});
    }
    return v;
  };
  std::vector<IPoint> v = make(true);
  const IPoint o{0, 0};
  bool ok = true;
  double total = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const IPoint &a = v[i], &b = v[(i + 1) % n];
    ok = ok && cross(o, a, b) > 0;
    total += std::atan2(static_cast<double>(cross(o, a, b)), static_cast<double>(dot(o, a, b)));
  }
  ok = ok && std::abs(total - 2 * M_PI) < 1e-6;  // winds once around the origin
  return ok ? v : make(false);
}

}  // namespace detail

// ---- PSLG families ----------------------------------------------------------

/// Convex polygon: the hull of random points of [0,12]^2, magnified by m in
/// [1, 4], every side sampled at each lattice point on it (the paper's class:
/// the shortest edges on the boundary). "gen:convex"
inline rc::Gen<Pslg> convexPolygon(double scale = 1) {
  return rc::gen::apply(
      [scale](const std::vector<std::pair<int, int>>& raw, int magnify) {
        std::vector<IPoint> pts;
        for (const auto& [x, y] : raw) pts.push_back({x, y});
        std::vector<IPoint> hull = detail::convex_hull(pts);
        if (hull.size() < 3) hull = {{0, 0}, {12, 0}, {0, 12}};
        for (IPoint& p : hull) p = {p.x * magnify, p.y * magnify};
        detail::Builder b;
        b.ring(hull, 1, 1);
        return b.build("gen:convex", scale);
      },
      rc::gen::container<std::vector<std::pair<int, int>>>(
          rc::gen::pair(rc::gen::inRange(0, 13), rc::gen::inRange(0, 13))),
      rc::gen::inRange(1, 5));
}

/// Non-convex (star-shaped) polygon with 4 to 12 corners at radii 12 to 32,
/// magnified by m in [1, 3] and sampled at every lattice point of its sides. "gen:star"
inline rc::Gen<Pslg> starPolygon(double scale = 1) {
  return rc::gen::mapcat(rc::gen::inRange(4, 13), [scale](int n) {
    return rc::gen::apply(
        [scale](const std::vector<std::pair<int, int>>& jr, int magnify) {
          std::vector<IPoint> ring = detail::star(jr, 24);
          for (IPoint& p : ring) p = {p.x * magnify, p.y * magnify};
          detail::Builder b;
          b.ring(ring, 1, 1);
          return b.build("gen:star", scale);
        },
        rc::gen::container<std::vector<std::pair<int, int>>>(
            static_cast<std::size_t>(n), rc::gen::pair(rc::gen::inRange(-40, 41), rc::gen::inRange(12, 33))),
        rc::gen::inRange(1, 4));
  });
}

/// Star-shaped polygon (6 to 12 corners, radii 24 to 40) with a star-shaped hole
/// (4 to 6 corners, radii 4 to 8) around the origin, hole point at the origin;
/// sides sampled at lattice points after magnifying by m in [1, 3]. "gen:hole"
inline rc::Gen<Pslg> polygonWithHole(double scale = 1) {
  return rc::gen::mapcat(rc::gen::pair(rc::gen::inRange(6, 13), rc::gen::inRange(4, 7)), [scale](std::pair<int, int> n) {
    return rc::gen::apply(
        [scale](const std::vector<std::pair<int, int>>& outer, const std::vector<std::pair<int, int>>& inner, int magnify) {
          std::vector<IPoint> o = detail::star(outer, 32), h = detail::star(inner, 6);
          for (IPoint& p : o) p = {p.x * magnify, p.y * magnify};
          for (IPoint& p : h) p = {p.x * magnify, p.y * magnify};
          detail::Builder b;
          b.ring(o, 1, 1);
          b.ring(h, 1, 2);
          b.hole({0, 0});
          return b.build("gen:hole", scale);
        },
        rc::gen::container<std::vector<std::pair<int, int>>>(
            static_cast<std::size_t>(n.first), rc::gen::pair(rc::gen::inRange(-40, 41), rc::gen::inRange(24, 41))),
        rc::gen::container<std::vector<std::pair<int, int>>>(
            static_cast<std::size_t>(n.second), rc::gen::pair(rc::gen::inRange(-20, 21), rc::gen::inRange(4, 9))),
        rc::gen::inRange(1, 4));
  });
}

/// Points in a box: the box [0,W]x[0,H] (W, H in [2, 32]), its sides sampled every
/// `stride` lattice points (0: corners only), 0 to 40 interior points. "gen:cloud"
inline rc::Gen<Pslg> pointCloudInBox(double scale = 1) {
  return rc::gen::apply(
      [scale](int w, int h, int stride, const std::vector<std::pair<int, int>>& raw) {
        detail::Builder b;
        b.ring({{0, 0}, {w, 0}, {w, h}, {0, h}}, stride, 1);
        for (std::size_t i = 0; i < raw.size() && i < 40; ++i) {
          const IPoint p{1 + raw[i].first % (w - 1), 1 + raw[i].second % (h - 1)};
          if (!b.occupied(p)) b.vertex(p);
        }
        return b.build("gen:cloud", scale);
      },
      rc::gen::inRange(2, 33), rc::gen::inRange(2, 33), rc::gen::inRange(0, 5),
      rc::gen::container<std::vector<std::pair<int, int>>>(rc::gen::pair(rc::gen::inRange(0, 64), rc::gen::inRange(0, 64))));
}

/// Interior cracks: the box [0,W]x[0,H] (W, H in [8, 32]) with up to 6 dangling
/// segments between interior lattice points (a crack that would touch an earlier
/// one, or a vertex, is dropped) and a few interior points. "gen:cracks"
inline rc::Gen<Pslg> boxWithCracks(double scale = 1) {
  using Quad = std::array<int, 4>;
  return rc::gen::apply(
      [scale](int w, int h, const std::vector<Quad>& cracks, const std::vector<std::pair<int, int>>& raw) {
        detail::Builder b;
        b.ring({{0, 0}, {w, 0}, {w, h}, {0, h}}, 0, 1);
        auto inside = [&](int x, int y) { return IPoint{1 + x % (w - 1), 1 + y % (h - 1)}; };
        for (std::size_t i = 0; i < cracks.size() && i < 6; ++i) {
          const Quad& c = cracks[i];
          const IPoint p = inside(c[0], c[1]), q = inside(c[2], c[3]);
          if (!b.blocked(p, q)) b.path(p, q, 0, 3);
        }
        for (std::size_t i = 0; i < raw.size() && i < 6; ++i) {
          const IPoint p = inside(raw[i].first, raw[i].second);
          if (!b.occupied(p)) b.vertex(p);
        }
        return b.build("gen:cracks", scale);
      },
      rc::gen::inRange(8, 33), rc::gen::inRange(8, 33),
      rc::gen::container<std::vector<Quad>>(
          rc::gen::apply([](int a, int b, int c, int d) { return Quad{a, b, c, d}; }, rc::gen::inRange(0, 64),
                         rc::gen::inRange(0, 64), rc::gen::inRange(0, 64), rc::gen::inRange(0, 64))),
      rc::gen::container<std::vector<std::pair<int, int>>>(rc::gen::pair(rc::gen::inRange(0, 64), rc::gen::inRange(0, 64))));
}

/// Near-degenerate input, one of: a collinear run of points across a box; the
/// lattice points of a circle (x^2 + y^2 = r^2 with many solutions) in a box; a full
/// grid of interior points (cocircular quadruples everywhere); a crack with a row of
/// points at distances k / |crack| from its line ("points close to segments").
/// "gen:collinear", "gen:cocircular", "gen:grid", "gen:close"
inline rc::Gen<Pslg> nearDegenerate(double scale = 1) {
  auto collinear = rc::gen::apply(
      [scale](int w, int step) {
        detail::Builder b;
        b.ring({{0, 0}, {w, 0}, {w, w}, {0, w}}, 0, 1);
        for (int x = step; x < w; x += step) b.vertex({x, w / 2});
        for (int x = step; x < w; x += step)
          if (!b.occupied({x, x})) b.vertex({x, x});
        return b.build("gen:collinear", scale);
      },
      rc::gen::inRange(4, 41), rc::gen::inRange(1, 4));
  auto cocircular = rc::gen::apply(
      [scale](int which, bool center) {
        static const std::int64_t kR2[] = {25, 50, 65, 85, 125, 325, 425};
        const std::int64_t r2 = kR2[which];
        const auto r = static_cast<std::int64_t>(std::sqrt(static_cast<double>(r2)));
        detail::Builder b;
        b.ring({{-r - 2, -r - 2}, {r + 2, -r - 2}, {r + 2, r + 2}, {-r - 2, r + 2}}, 0, 1);
        for (std::int64_t x = -r; x <= r; ++x)
          for (std::int64_t y = -r; y <= r; ++y)
            if (x * x + y * y == r2) b.vertex({x, y});
        if (center) b.vertex({0, 0});
        return b.build("gen:cocircular", scale);
      },
      rc::gen::inRange(0, 7), rc::gen::arbitrary<bool>());
  auto grid = rc::gen::apply(
      [scale](int a, int c) {
        detail::Builder b;
        b.ring({{0, 0}, {a + 1, 0}, {a + 1, c + 1}, {0, c + 1}}, 1, 1);
        for (int x = 1; x <= a; ++x)
          for (int y = 1; y <= c; ++y) b.vertex({x, y});
        return b.build("gen:grid", scale);
      },
      rc::gen::inRange(1, 9), rc::gen::inRange(1, 9));
  auto close = rc::gen::apply(
      [scale](int w) {
        detail::Builder b;
        b.ring({{0, 0}, {w, 0}, {w, w}, {0, w}}, 0, 1);
        b.path({1, 1}, {w - 2, w - 3}, 0, 3);  // direction (w-3, w-4): cross with (k, k) is k
        for (int k = 1; k + 1 < w - 2; ++k) b.vertex({1 + k, 1 + k});
        return b.build("gen:close", scale);
      },
      rc::gen::inRange(6, 41));
  return rc::gen::oneOf(collinear, cocircular, grid, close);
}

/// Small input angles: a wedge of angle phi in [1, 59] degrees at the origin, sides
/// of length L in [64, 1024] (phi is the lattice-rounded angle, within 1 degree), as
/// a convex polygon (the wedge side on the x axis sampled every L/8) or as two cracks
/// inside a box. "gen:wedge", "gen:wedge-cracks"
inline rc::Gen<Pslg> smallInputAngle(double scale = 1) {
  return rc::gen::apply(
      [scale](int phi, int length, bool cracks) {
        const double a = phi * M_PI / 180;
        const std::int64_t L = length;
        const IPoint o{0, 0}, p1{L, 0};
        IPoint p2{std::lround(L * std::cos(a)), std::lround(L * std::sin(a))};
        if (p2.y == 0) p2.y = 1;
        if (cracks) {
          detail::Builder b;
          b.ring({{-L / 2, -L / 2}, {L + L / 2, -L / 2}, {L + L / 2, L + L / 2}, {-L / 2, L + L / 2}}, 0, 1);
          b.path(o, p1, L / 8, 3);
          b.path(o, p2, 0, 3);
          return b.build("gen:wedge-cracks", scale);
        }
        const IPoint q{std::lround(1.3 * L * std::cos(a / 2)), std::lround(1.3 * L * std::sin(a / 2))};
        const bool convex = detail::cross(o, p1, q) > 0 && detail::cross(p1, q, p2) > 0 && detail::cross(q, p2, o) > 0;
        std::vector<IPoint> ring = convex ? std::vector<IPoint>{o, p1, q, p2} : std::vector<IPoint>{o, p1, p2};
        // The x-axis side sampled every L/8; the others at their lattice points, if any.
        detail::Builder fine;
        std::vector<IPoint> corners;
        for (std::size_t i = 0; i < ring.size(); ++i) {
          corners.push_back(ring[i]);
          if (i == 0)
            for (std::int64_t k = 1; k < 8; ++k) corners.push_back({k * L / 8, 0});
        }
        fine.ring(corners, 0, 1);
        return fine.build("gen:wedge", scale);
      },
      rc::gen::inRange(1, 60), rc::gen::inRange(64, 1025), rc::gen::arbitrary<bool>());
}

/// Any of the families above.
inline rc::Gen<Pslg> anyPslg(double scale = 1) {
  return rc::gen::oneOf(convexPolygon(scale), starPolygon(scale), polygonWithHole(scale), pointCloudInBox(scale),
                        boxWithCracks(scale), nearDegenerate(scale), smallInputAngle(scale));
}

/// PSLGs whose input angles are all >= 60 degrees (the class of the paper's
/// termination results): boxes with interior points, sampled sides and square
/// holes, and regular polygons with 6 to 12 sides. "gen:cloud", "gen:regular", "gen:box-hole"
inline rc::Gen<Pslg> wellShapedPslg(double scale = 1) {
  auto regular = rc::gen::apply(
      [scale](int n, int radius, int stride) {
        std::vector<std::pair<int, int>> jr(static_cast<std::size_t>(n), {0, radius});
        detail::Builder b;
        b.ring(detail::star(jr, radius), stride, 1);
        return b.build("gen:regular", scale);
      },
      rc::gen::inRange(6, 13), rc::gen::inRange(8, 33), rc::gen::inRange(0, 3));
  auto box_hole = rc::gen::apply(
      [scale](int w, int h, int hx, int hy, int hw, int hh, int stride) {
        detail::Builder b;
        b.ring({{0, 0}, {w, 0}, {w, h}, {0, h}}, stride, 1);
        // The hole [x0, x0+hw] x [y0, y0+hh] strictly inside the box.
        const int x0 = 1 + hx % std::max(1, w - hw - 1), y0 = 1 + hy % std::max(1, h - hh - 1);
        const int x1 = std::min(x0 + hw, w - 1), y1 = std::min(y0 + hh, h - 1);
        if (x1 > x0 && y1 > y0) {
          b.ring({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, stride, 2);
          // The hole point: the centre, or inside the first lattice cell (never on a segment).
          b.hole({x0, y0});
          Pslg p = b.build("gen:box-hole", scale);
          p.holes[0] = {(x0 + 0.5) * scale, (y0 + 0.5) * scale};
          return p;
        }
        return b.build("gen:box-hole", scale);
      },
      rc::gen::inRange(4, 33), rc::gen::inRange(4, 33), rc::gen::inRange(0, 32), rc::gen::inRange(0, 32), rc::gen::inRange(1, 16),
      rc::gen::inRange(1, 16), rc::gen::inRange(0, 3));
  return rc::gen::oneOf(pointCloudInBox(scale), regular, box_hole);
}

// ---- triangles and terminal pairs ------------------------------------------

/// A non-degenerate counter-clockwise triangle with vertices in [-64, 64]^2.
inline rc::Gen<std::array<Point, 3>> triangle(double scale = 1) {
  auto corner = rc::gen::pair(rc::gen::inRange(-64, 65), rc::gen::inRange(-64, 65));
  return rc::gen::map(
      rc::gen::suchThat(rc::gen::tuple(corner, corner, corner),
                        [](const auto& t) {
                          const auto& [a, b, c] = t;
                          return detail::cross({a.first, a.second}, {b.first, b.second}, {c.first, c.second}) != 0;
                        }),
      [scale](const auto& t) {
        const auto& [a, b, c] = t;
        std::array<Point, 3> tri{Point{a.first * scale, a.second * scale}, Point{b.first * scale, b.second * scale},
                                 Point{c.first * scale, c.second * scale}};
        if (detail::cross({a.first, a.second}, {b.first, b.second}, {c.first, c.second}) < 0) std::swap(tri[1], tri[2]);
        return tri;
      });
}

/// Two triangles t1 = (a, b, c) and t2 = (b, a, d), both counter-clockwise, sharing
/// the edge ab that is strictly the longest edge of both (a terminal edge), with d
/// not strictly inside the circumcircle of abc (locally Delaunay: cocircular allowed).
struct TerminalPair {
  Point a, b, c, d;
};

/// Delaunay terminal pairs: ab = (0,0)-(L,0), L in [2, 64], c above and d below
/// inside the lens |ac|, |bc|, |ad|, |bd| < L, locally Delaunay; then one of the 8
/// lattice symmetries and a translation in [-64, 64]^2.
inline rc::Gen<TerminalPair> delaunayTerminalPair(double scale = 1) {
  using Raw = std::array<int, 5>;  // L, cx, cy, dx, dy (cy > 0, dy > 0 below the axis)
  auto raw = rc::gen::mapcat(rc::gen::inRange(2, 65), [](int L) {
    const int h = static_cast<int>(std::ceil(L * 0.8661));
    return rc::gen::suchThat(
        rc::gen::apply([L](int cx, int cy, int dx, int dy) { return Raw{L, cx, cy, dx, dy}; }, rc::gen::inRange(1, L),
                       rc::gen::inRange(1, h + 1), rc::gen::inRange(1, L), rc::gen::inRange(1, h + 1)),
        [](const Raw& r) {
          const std::int64_t L = r[0];
          const IPoint a{0, 0}, b{L, 0}, c{r[1], r[2]}, d{r[3], -r[4]};
          auto shorter = [&](const IPoint& p, const IPoint& q) {
            return (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y) < L * L;
          };
          if (!shorter(a, c) || !shorter(b, c) || !shorter(a, d) || !shorter(b, d)) return false;
          // With a at the origin, det[b |b|^2; c |c|^2; d |d|^2] < 0 iff d is strictly inside
          // the circle through the CCW triangle abc.
          auto lift = [](const IPoint& p) { return p.x * p.x + p.y * p.y; };
          const __int128 det = static_cast<__int128>(b.x) * (static_cast<__int128>(c.y) * lift(d) - static_cast<__int128>(lift(c)) * d.y) -
                               static_cast<__int128>(b.y) * (static_cast<__int128>(c.x) * lift(d) - static_cast<__int128>(lift(c)) * d.x) +
                               static_cast<__int128>(lift(b)) * (static_cast<__int128>(c.x) * d.y - static_cast<__int128>(c.y) * d.x);
          return det >= 0;
        });
  });
  return rc::gen::apply(
      [scale](const Raw& r, int symmetry, int tx, int ty) {
        auto map = [&](std::int64_t x, std::int64_t y) {
          // 4 rotations by 90 degrees, optionally after a reflection that is then undone
          // in orientation by swapping the roles below.
          for (int k = 0; k < symmetry % 4; ++k) {
            const std::int64_t t = x;
            x = -y;
            y = t;
          }
          return Point{static_cast<double>(x + tx) * scale, static_cast<double>(y + ty) * scale};
        };
        TerminalPair p{map(0, 0), map(r[0], 0), map(r[1], r[2]), map(r[3], -r[4])};
        if (symmetry >= 4) {  // the mirror image: swap a and b, c and d keeps both triangles CCW
          auto mirror = [&](std::int64_t x, std::int64_t y) { return map(r[0] - x, y); };
          p = TerminalPair{mirror(r[0], 0), mirror(0, 0), mirror(r[1], r[2]), mirror(r[3], -r[4])};
        }
        return p;
      },
      raw, rc::gen::inRange(0, 8), rc::gen::inRange(-64, 65), rc::gen::inRange(-64, 65));
}

// ---- helpers for properties ---------------------------------------------------

/// RapidCheck prints a shrunk TerminalPair as its four points.
inline void showValue(const TerminalPair& q, std::ostream& os) {
  os << "a (" << q.a.x << ", " << q.a.y << ") b (" << q.b.x << ", " << q.b.y << ") c (" << q.c.x << ", " << q.c.y << ") d ("
     << q.d.x << ", " << q.d.y << ")";
}

/// The smallest angle in degrees between two segments sharing an endpoint (180 when
/// no two segments share one), in double: for classifying, not for deciding.
inline double min_input_angle_deg(const Pslg& p) {
  double best = 180;
  for (std::size_t i = 0; i < p.segments.size(); ++i)
    for (std::size_t j = i + 1; j < p.segments.size(); ++j) {
      const Segment &s = p.segments[i], &t = p.segments[j];
      int v = -1, a = -1, b = -1;
      if (s.a == t.a) v = s.a, a = s.b, b = t.b;
      else if (s.a == t.b) v = s.a, a = s.b, b = t.a;
      else if (s.b == t.a) v = s.b, a = s.a, b = t.b;
      else if (s.b == t.b) v = s.b, a = s.a, b = t.a;
      if (v < 0) continue;
      const Point &o = p.vertices[static_cast<std::size_t>(v)], &x = p.vertices[static_cast<std::size_t>(a)],
                  &y = p.vertices[static_cast<std::size_t>(b)];
      best = std::min(best, angle_deg(o, x, y));  // scaled vectors: right at 1e299 and 1e-301 too
    }
  return best;
}

}  // namespace lepp::gen

namespace lepp {
/// RapidCheck prints a shrunk PSLG as a Triangle .poly file (1-based), ready to save and replay.
inline void showValue(const Pslg& p, std::ostream& os) {
  os << "# " << p.source << "\n" << p.vertices.size() << " 2 0 0\n";
  for (std::size_t i = 0; i < p.vertices.size(); ++i) os << i + 1 << " " << p.vertices[i].x << " " << p.vertices[i].y << "\n";
  os << p.segments.size() << " 0\n";
  for (std::size_t i = 0; i < p.segments.size(); ++i) os << i + 1 << " " << p.segments[i].a + 1 << " " << p.segments[i].b + 1 << "\n";
  os << p.holes.size() << "\n";
  for (std::size_t i = 0; i < p.holes.size(); ++i) os << i + 1 << " " << p.holes[i].x << " " << p.holes[i].y << "\n";
}
}  // namespace lepp
