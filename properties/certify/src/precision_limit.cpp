// SPDX-License-Identifier: GPL-3.0-or-later
// The precision-limit exemption (docs/CERTIFIER.md section 5c): enumerate every
// Lepp and every branch of Select Point the paper allows, round each point in
// every way, and ask whether any of them can be inserted.
#include "precision_limit.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <set>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "exact.h"
#include "lepp/rounding.h"

namespace lepp::certify {
namespace {

// A point to try: its coordinates and how it was rounded (-1 down, 0 exact, 1 up;
// kFormula for the engines' formula).
constexpr int kFormula = 2;
struct Candidate {
  Point p;
  int rx = kFormula, ry = kFormula;
};

std::string rounding_text(const Candidate& c) {
  if (c.rx == kFormula) return "formula";
  auto word = [](int r) { return r < 0 ? "down" : r > 0 ? "up" : "exact"; };
  return fmt::format("x {}, y {}", word(c.rx), word(c.ry));
}

class Search {
 public:
  Search(const PrecisionView& v, Method method, const PrecisionLimits& limits) : v_(v), method_(method), limits_(limits) {}

  // Whether every choice for triangle t, at every rounding, is not insertable.
  PrecisionClaim claim(std::size_t t) {
    PrecisionClaim out;
    out.triangle = static_cast<int>(t);
    out.outcome = PrecisionOutcome::Exempt;
    for (int h : longest(static_cast<int>(t)))
      if (!walk(h)) {
        out.outcome = stopped_ ? PrecisionOutcome::Undecided : PrecisionOutcome::Rejected;
        out.undecided = why_;
        out.witness = std::move(witness_);
        break;
      }
    // The states followed: at the bound, the one past it was only counted.
    out.states = stopped_ && why_ == PrecisionUndecided::Bound ? seen_.size() - 1 : seen_.size();
    return out;
  }

 private:
  const PrecisionView& v_;
  Method method_;
  const PrecisionLimits& limits_;
  std::set<int> seen_;     // half-edges taken as a triangle's longest edge
  std::vector<int> path_;  // the half-edges of the current Lepp, taken as longest
  bool stopped_ = false;   // stopped undecided, for the reason why_
  PrecisionUndecided why_ = PrecisionUndecided::Bound;
  PrecisionWitness witness_;  // the insertable choice found

  bool stop(PrecisionUndecided why) {
    stopped_ = true;
    why_ = why;
    return false;
  }
  // The choice that reaches c, from the current path (its last half-edge the terminal
  // edge; g across it, or -1): recorded, and false (the search ends there).
  bool found(const Candidate& c, Rule rule, int g, int s1, int s2, int split) {
    witness_.point = c.p;
    witness_.rounding = rounding_text(c);
    witness_.rule = rule;
    for (int h : path_) {
      witness_.lepp.push_back(h / 3);
      witness_.longest.push_back({from(h), to(h)});
    }
    witness_.terminal_other = g < 0 ? -1 : g / 3;
    auto edge = [&](int h) { return h < 0 ? std::array<int, 2>{{-1, -1}} : std::array<int, 2>{{from(h), to(h)}}; };
    witness_.second1 = edge(s1);
    witness_.second2 = edge(s2);
    witness_.split = edge(split);
    return false;
  }

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
    if (limits_.ties_by_ids && out.size() > 1) out = {id_longest(out)};
    return out;
  }
  // Every second-longest half-edge of t when l is its longest: the longer of the other two, ties kept.
  std::vector<int> second(int l) const {
    const int t = l / 3, a = 3 * t + (l % 3 + 1) % 3, b = 3 * t + (l % 3 + 2) % 3;
    const int c = len_cmp(a, b);
    if (c > 0) return {a};
    if (c < 0) return {b};
    if (limits_.ties_by_ids) return {id_longest({a, b})};
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
  // soon as one choice can be inserted (witness_), or the search stops undecided.
  bool walk(int h) {
    if (!seen_.insert(h).second) return true;
    if (limits_.states > 0 && seen_.size() > limits_.states) return stop(PrecisionUndecided::Bound);  // no exemption
    if (limits_.deadline && std::chrono::steady_clock::now() > *limits_.deadline) return stop(PrecisionUndecided::TimeLimit);
    if (!v_.tri_ok[static_cast<std::size_t>(h / 3)]) return stop(PrecisionUndecided::BadMesh);
    const int g = v_.twin[static_cast<std::size_t>(h)];
    if (g == -2) return stop(PrecisionUndecided::BadMesh);
    path_.push_back(h);
    if (constrained(h)) {  // one terminal triangle
      const std::vector<Candidate> ps = midpoints(h);
      if (const int i = split_insertable_any(h, ps); i >= 0)
        return found(ps[static_cast<std::size_t>(i)], Rule::TerminalConstrainedMidpoint, -1, -1, -1, h);
      path_.pop_back();
      return true;
    }
    const std::vector<int> next = longest(g / 3);
    for (int e : next) {
      if (e == g) {
        if (!pair_limited(h, g)) return false;
      } else if (!walk(e)) {
        return false;
      }
    }
    path_.pop_back();
    return true;
  }

  // The formula's double, then the doubles a mesher may round the exact point to
  // (each coordinate truncated or rounded the other way, lepp/rounding.h).
  static std::vector<Candidate> points(const DoublesAround& xs, const DoublesAround& ys, const Point& formula) {
    auto way = [](const DoublesAround& d, int i) { return d.count == 1 ? 0 : i == 0 ? -1 : 1; };
    std::vector<Candidate> out{{formula, kFormula, kFormula}};
    for (int i = 0; i < xs.count; ++i)
      for (int j = 0; j < ys.count; ++j) out.push_back({{xs.value[i], ys.value[j]}, way(xs, i), way(ys, j)});
    return out;
  }
  std::vector<Candidate> midpoints(int h) const {
    const Point &a = P(from(h)), &b = P(to(h));
    return points(doubles_around_midpoint(a.x, b.x), doubles_around_midpoint(a.y, b.y), {(a.x + b.x) * 0.5, (a.y + b.y) * 0.5});
  }
  std::vector<Candidate> centroids(int h, int g) const {
    const Point &a = P(from(h)), &b = P(to(h)), &c = P(apex(h)), &d = P(apex(g));
    return points(doubles_around_centroid(a.x, b.x, c.x, d.x), doubles_around_centroid(a.y, b.y, c.y, d.y),
                  {((a.x + b.x) + (c.x + d.x)) * 0.25, ((a.y + b.y) + (c.y + d.y)) * 0.25});
  }

  // The terminal pair (h, g): every branch of Select Point (method), every second-longest tie.
  bool pair_limited(int h, int g) {
    for (int s1 : second(h))
      for (int s2 : second(g)) {
        const bool c1 = constrained(s1), c2 = constrained(s2);
        // The midpoint of constrained edge s, split, when one of its roundings can be inserted.
        auto split = [&](int s, Rule rule) {
          const std::vector<Candidate> ps = midpoints(s);
          const int i = split_insertable_any(s, ps);
          return i >= 0 && !found(ps[static_cast<std::size_t>(i)], rule, g, s1, s2, s);
        };
        auto located = [&](const std::vector<Candidate>& ps, Rule rule) {
          const int i = located_insertable_any(h, ps);
          return i >= 0 && !found(ps[static_cast<std::size_t>(i)], rule, g, s1, s2, -1);
        };
        if (method_ == Method::Midpoint) {
          if (!c1 && !c2) {
            if (located(midpoints(h), Rule::TerminalMidpoint)) return false;
          } else {
            if (c1 && split(s1, Rule::SecondLongestMidpoint)) return false;
            if (c2 && split(s2, Rule::SecondLongestMidpoint)) return false;
          }
          continue;
        }
        if (!c1 && !c2) {
          if (located(centroids(h, g), Rule::QuadCentroid)) return false;
        } else if (c1 && c2) {
          if (split(s1, Rule::BothSecondLongestMidpoint) || split(s2, Rule::BothSecondLongestMidpoint)) return false;
        } else {
          // Remark 10: the centroid if strictly inside the other triangle, else the midpoint of l*.
          // The midpoint is a choice only when some rounding of the centroid is not strictly
          // inside (the four directed roundings box the exact centroid: all four strictly inside
          // the convex triangle means the exact one is too, and no mesher may take the midpoint).
          const int other = c1 ? g / 3 : h / 3, star_edge = c1 ? s1 : s2;
          bool outside = false;
          for (const Candidate& c : centroids(h, g)) {
            if (!strictly_inside(other, c.p)) outside = true;
            else if (!near_pair_vertex(h, c.p)) return found(c, Rule::CentroidInOther, g, s1, s2, -1);
          }
          if (outside && split(star_edge, Rule::SecondLongestMidpoint)) return false;
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
  // The index of the first that can be inserted, or -1.
  int located_insertable_any(int h, const std::vector<Candidate>& ps) const {
    const int g = v_.twin[static_cast<std::size_t>(h)];
    for (std::size_t i = 0; i < ps.size(); ++i) {
      const Point& p = ps[i].p;
      if (near_pair_vertex(h, p)) continue;
      const int first = place_in(h / 3, p);
      if (first > 0 || (first == 0 && place_in(g / 3, p) > 0)) return static_cast<int>(i);
    }
    return -1;
  }
  // The split of edge h at p: every triangle it makes, on each side, counter-clockwise;
  // on the mesh boundary with p strictly outside, the closed sliver a, p, b free of
  // the input outside the domain and of the mesh's own chains (the sliver clause, as
  // the reference decides it on its whole triangulation: where a nearly parallel
  // segment leaves a or b, its chain may pass through the sliver). A mesh vertex in
  // the sliver implies a chain edge meeting it in a mesh the coverage checks pass.
  // A linear scan: only bad triangles on the boundary come here. The index of the
  // first point that can be inserted, or -1.
  int split_insertable_any(int h, const std::vector<Candidate>& ps) const {
    const int g = v_.twin[static_cast<std::size_t>(h)];
    const Point &a = P(from(h)), &b = P(to(h)), &c = P(apex(h));
    for (std::size_t i = 0; i < ps.size(); ++i) {
      const Point& p = ps[i].p;
      if (exact::orient(a, p, c) <= 0 || exact::orient(p, b, c) <= 0) continue;
      if (below_precision_floor(p, a) || below_precision_floor(p, b) || below_precision_floor(p, c)) continue;
      if (g >= 0) {
        const Point& d = P(apex(g));
        if (exact::orient(b, p, d) <= 0 || exact::orient(p, a, d) <= 0 || below_precision_floor(p, d)) continue;
      } else if (exact::orient(a, b, p) < 0 &&
                 (sliver_blocked(v_.outside, a, b, p, exact::orient) || sliver_blocked(v_.chains, a, b, p, exact::orient))) {
        continue;
      }
      return static_cast<int>(i);
    }
    return -1;
  }
};

}  // namespace

PrecisionClaim precision_claim(const PrecisionView& view, std::size_t t, Method method, const PrecisionLimits& limits) {
  if (!view.tri_ok[t]) {
    PrecisionClaim bad;
    bad.triangle = static_cast<int>(t);
    bad.undecided = PrecisionUndecided::BadMesh;
    return bad;
  }
  return Search(view, method, limits).claim(t);
}

}  // namespace lepp::certify
