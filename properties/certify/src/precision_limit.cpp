// SPDX-License-Identifier: GPL-3.0-or-later
// The precision-limit exemption (docs/CERTIFIER.md section 5c): enumerate every
// Lepp and every branch of Select Point the paper allows, round each point in
// every way, and ask whether any of them can be inserted.
#include "precision_limit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <utility>

#include "exact.h"
#include "lepp/rounding.h"

namespace lepp::certify {
namespace {

class Search {
 public:
  Search(const PrecisionView& v, Method method, bool ties_by_ids) : v_(v), method_(method), by_ids_(ties_by_ids) {}

  // Whether every choice for triangle t, at every rounding, is not insertable.
  PrecisionVerdict verdict(std::size_t t) {
    for (int h : longest(static_cast<int>(t)))
      if (!walk(h)) return too_big_ || undecided_ ? PrecisionVerdict::Undecided : PrecisionVerdict::Insertable;
    return too_big_ ? PrecisionVerdict::Undecided : PrecisionVerdict::Limited;
  }

 private:
  const PrecisionView& v_;
  Method method_;
  bool by_ids_;  // equal lengths decided by vertex ids, as lepp's edge order (ALGORITHM.md section 3)
  std::set<int> seen_;  // half-edges taken as a triangle's longest edge
  bool too_big_ = false;
  bool undecided_ = false;  // a bad triangle or edge met: no choice can be judged there

  const Tri& T(int t) const { return v_.mesh.triangles[static_cast<std::size_t>(t)]; }
  const Point& P(int id) const { return v_.mesh.vertices[static_cast<std::size_t>(id)]; }
  int from(int h) const { return T(h / 3)[static_cast<std::size_t>(h % 3)]; }
  int to(int h) const { return T(h / 3)[static_cast<std::size_t>((h % 3 + 1) % 3)]; }
  int apex(int h) const { return T(h / 3)[static_cast<std::size_t>((h % 3 + 2) % 3)]; }
  int len_cmp(int h, int g) const { return exact::compare_squared_length(P(from(h)), P(to(h)), P(from(g)), P(to(g))); }
  // A segment chain or the mesh boundary: the paper's constrained edges.
  bool constrained(int h) const { return v_.chain[static_cast<std::size_t>(h)] || v_.twin[static_cast<std::size_t>(h)] == -1; }

  // Every longest half-edge of triangle t (exact lengths, ties kept).
  std::vector<int> longest(int t) const {
    std::vector<int> out;
    for (int i = 0; i < 3; ++i) {
      const int h = 3 * t + i;
      bool max = true;
      for (int j = 0; j < 3 && max; ++j) max = j == i || len_cmp(h, 3 * t + j) >= 0;
      if (max) out.push_back(h);
    }
    if (by_ids_ && out.size() > 1) out = {id_longest(out)};
    return out;
  }
  // Every second-longest half-edge of t when l is its longest: the longer of the other two, ties kept.
  std::vector<int> second(int l) const {
    const int t = l / 3, a = 3 * t + (l % 3 + 1) % 3, b = 3 * t + (l % 3 + 2) % 3;
    const int c = len_cmp(a, b);
    if (c > 0) return {a};
    if (c < 0) return {b};
    if (by_ids_) return {id_longest({a, b})};
    return {a, b};
  }
  // Among half-edges of equal length, the longest in lepp's edge order: the smaller
  // smaller endpoint id, then the smaller larger one.
  int id_longest(const std::vector<int>& hs) const {
    auto key = [&](int h) { return std::make_pair(-std::min(from(h), to(h)), -std::max(from(h), to(h))); };
    int best = hs[0];
    for (int h : hs)
      if (key(h) > key(best)) best = h;
    return best;
  }

  // The Lepp from the triangle of h with h taken as its longest edge: false as
  // soon as one choice can be inserted.
  bool walk(int h) {
    if (!seen_.insert(h).second) return true;
    if (seen_.size() > kTieSearchStates) return !(too_big_ = true);  // beyond the bound: no exemption
    if (!v_.tri_ok[static_cast<std::size_t>(h / 3)]) return !(undecided_ = true);
    const int g = v_.twin[static_cast<std::size_t>(h)];
    if (g == -2) return !(undecided_ = true);
    if (constrained(h)) return !split_insertable_any(h, midpoints(h));  // one terminal triangle
    const std::vector<int> next = longest(g / 3);
    for (int e : next) {
      if (e == g) {
        if (!pair_limited(h, g)) return false;
      } else if (!walk(e)) {
        return false;
      }
    }
    return true;
  }

  // The formula's double, then the doubles a mesher may round the exact point to
  // (each coordinate truncated or rounded the other way, lepp/rounding.h).
  static std::vector<Point> points(const DoublesAround& xs, const DoublesAround& ys, const Point& formula) {
    std::vector<Point> out{formula};
    for (double px : xs)
      for (double py : ys) out.push_back({px, py});
    return out;
  }
  std::vector<Point> midpoints(int h) const {
    const Point &a = P(from(h)), &b = P(to(h));
    return points(doubles_around_midpoint(a.x, b.x), doubles_around_midpoint(a.y, b.y), {(a.x + b.x) * 0.5, (a.y + b.y) * 0.5});
  }
  std::vector<Point> centroids(int h, int g) const {
    const Point &a = P(from(h)), &b = P(to(h)), &c = P(apex(h)), &d = P(apex(g));
    return points(doubles_around_centroid(a.x, b.x, c.x, d.x), doubles_around_centroid(a.y, b.y, c.y, d.y),
                  {((a.x + b.x) + (c.x + d.x)) * 0.25, ((a.y + b.y) + (c.y + d.y)) * 0.25});
  }

  // The terminal pair (h, g): every branch of Select Point (method), every second-longest tie.
  bool pair_limited(int h, int g) {
    for (int s1 : second(h))
      for (int s2 : second(g)) {
        const bool c1 = constrained(s1), c2 = constrained(s2);
        if (method_ == Method::Midpoint) {
          if (!c1 && !c2) {
            if (located_insertable_any(h, midpoints(h))) return false;
          } else {
            if (c1 && split_insertable_any(s1, midpoints(s1))) return false;
            if (c2 && split_insertable_any(s2, midpoints(s2))) return false;
          }
          continue;
        }
        if (!c1 && !c2) {
          if (located_insertable_any(h, centroids(h, g))) return false;
        } else if (c1 && c2) {
          if (split_insertable_any(s1, midpoints(s1)) || split_insertable_any(s2, midpoints(s2))) return false;
        } else {
          // Remark 10: the centroid if strictly inside the other triangle, else the midpoint of l*.
          // The midpoint is a choice only when some rounding of the centroid is not strictly
          // inside (the four directed roundings box the exact centroid: all four strictly inside
          // the convex triangle means the exact one is too, and no mesher may take the midpoint).
          const int other = c1 ? g / 3 : h / 3, star_edge = c1 ? s1 : s2;
          bool outside = false;
          for (const Point& p : centroids(h, g)) {
            if (!strictly_inside(other, p)) outside = true;
            else if (!near_pair_vertex(h, p)) return false;
          }
          if (outside && split_insertable_any(star_edge, midpoints(star_edge))) return false;
        }
      }
    return true;
  }

  bool strictly_inside(int t, const Point& p) const {
    for (int i = 0; i < 3; ++i)
      if (exact::orient(P(T(t)[static_cast<std::size_t>(i)]), P(T(t)[static_cast<std::size_t>((i + 1) % 3)]), p) <= 0) return false;
    return true;
  }
  // 1 strictly inside t, 2 on an edge that is neither constrained nor bad, 0 outside, -1 otherwise.
  int place_in(int t, const Point& p) const {
    int zeros = 0, on = -1;
    for (int i = 0; i < 3; ++i) {
      const int o = exact::orient(P(T(t)[static_cast<std::size_t>(i)]), P(T(t)[static_cast<std::size_t>((i + 1) % 3)]), p);
      if (o < 0) return 0;
      if (o == 0) ++zeros, on = 3 * t + i;
    }
    if (zeros == 0) return 1;
    if (zeros >= 2) return -1;
    return constrained(on) || v_.twin[static_cast<std::size_t>(on)] < 0 ? -1 : 2;
  }
  // Within the precision floor (lepp::below_precision_floor, a few ulps) of a vertex
  // of the terminal pair of h: the engines' floor on the edges the point would make.
  bool near_pair_vertex(int h, const Point& p) const {
    const int g = v_.twin[static_cast<std::size_t>(h)];
    for (int half : {h, g}) {
      if (half < 0) continue;
      for (int v : T(half / 3))
        if (below_precision_floor(p, P(v))) return true;
    }
    return false;
  }
  // A point of the terminal quad of h (t1 = h's triangle, t2 across): in the closed
  // pair, off its vertices and off constrained edges, beyond the precision floor.
  bool located_insertable_any(int h, const std::vector<Point>& ps) const {
    const int g = v_.twin[static_cast<std::size_t>(h)];
    for (const Point& p : ps) {
      if (near_pair_vertex(h, p)) continue;
      const int first = place_in(h / 3, p);
      if (first > 0 || (first == 0 && place_in(g / 3, p) > 0)) return true;
    }
    return false;
  }
  // The split of edge h at p: every triangle it makes, on each side, counter-clockwise;
  // on the mesh boundary with p strictly outside, the closed sliver a, p, b free of
  // the input outside the domain and of the mesh's own chains (the sliver clause, as
  // the reference decides it on its whole triangulation: where a nearly parallel
  // segment leaves a or b, its chain may pass through the sliver). A mesh vertex in
  // the sliver implies a chain edge meeting it in a mesh the coverage checks pass.
  // A linear scan: only bad triangles on the boundary come here.
  bool split_insertable_any(int h, const std::vector<Point>& ps) const {
    const int g = v_.twin[static_cast<std::size_t>(h)];
    const Point &a = P(from(h)), &b = P(to(h)), &c = P(apex(h));
    for (const Point& p : ps) {
      if (exact::orient(a, p, c) <= 0 || exact::orient(p, b, c) <= 0) continue;
      if (below_precision_floor(p, a) || below_precision_floor(p, b) || below_precision_floor(p, c)) continue;
      if (g >= 0) {
        const Point& d = P(apex(g));
        if (exact::orient(b, p, d) <= 0 || exact::orient(p, a, d) <= 0 || below_precision_floor(p, d)) continue;
      } else if (exact::orient(a, b, p) < 0 &&
                 (sliver_blocked(v_.outside, a, b, p, exact::orient) || sliver_blocked(v_.chains, a, b, p, exact::orient))) {
        continue;
      }
      return true;
    }
    return false;
  }
};

}  // namespace

PrecisionVerdict precision_verdict(const PrecisionView& view, std::size_t t, Method method, bool ties_by_ids) {
  if (!view.tri_ok[t]) return PrecisionVerdict::Undecided;
  return Search(view, method, ties_by_ids).verdict(t);
}

}  // namespace lepp::certify
