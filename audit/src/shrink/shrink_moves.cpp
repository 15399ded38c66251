// SPDX-License-Identifier: GPL-3.0-or-later
// The greedy shrinker's edits: splices, pieces, rounding.
#include "shrink_moves.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace lepp::audit::detail {
namespace {

// Segment ids at each vertex.
std::vector<std::vector<int>> incidence(const Pslg& p) {
  std::vector<std::vector<int>> inc(p.vertices.size());
  for (std::size_t s = 0; s < p.segments.size(); ++s) {
    const Segment& seg = p.segments[s];
    if (seg.a < 0 || seg.b < 0 || seg.a >= static_cast<int>(inc.size()) || seg.b >= static_cast<int>(inc.size())) continue;
    inc[seg.a].push_back(static_cast<int>(s));
    if (seg.b != seg.a) inc[seg.b].push_back(static_cast<int>(s));
  }
  return inc;
}

int other_end(const Segment& s, int v) { return s.a == v ? s.b : s.a; }

// v has two segments to two different neighbours not joined by a segment yet.
bool can_splice(const std::vector<Segment>& segs, const std::vector<std::vector<int>>& inc, int v) {
  if (inc[v].size() != 2) return false;
  const int a = other_end(segs[inc[v][0]], v), b = other_end(segs[inc[v][1]], v);
  if (a == b || a == v || b == v) return false;
  for (int s : inc[a])
    if (other_end(segs[s], a) == b) return false;
  return true;
}

}  // namespace

Pslg without_vertices(const Pslg& p, const std::vector<char>& drop) {
  Pslg q;
  q.source = p.source;
  const bool markers = p.vertex_markers.size() == p.vertices.size();
  std::vector<int> id(p.vertices.size(), -1);
  for (std::size_t i = 0; i < p.vertices.size(); ++i) {
    if (i < drop.size() && drop[i]) continue;
    id[i] = static_cast<int>(q.vertices.size());
    q.vertices.push_back(p.vertices[i]);
    if (markers) q.vertex_markers.push_back(p.vertex_markers[i]);
  }
  for (const Segment& s : p.segments) {
    if (s.a < 0 || s.b < 0 || s.a >= static_cast<int>(id.size()) || s.b >= static_cast<int>(id.size())) continue;
    if (id[s.a] < 0 || id[s.b] < 0) continue;
    q.segments.push_back({id[s.a], id[s.b], s.marker});
  }
  q.holes = p.holes;
  return q;
}

std::vector<std::vector<int>> pieces(const Pslg& p) {
  const int n = static_cast<int>(p.vertices.size());
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const Segment& s : p.segments)
    if (s.a >= 0 && s.b >= 0 && s.a < n && s.b < n) parent[find(s.a)] = find(s.b);
  std::vector<int> slot(n, -1);
  std::vector<std::vector<int>> out;
  for (int v = 0; v < n; ++v) {
    const int r = find(v);
    if (slot[r] < 0) {
      slot[r] = static_cast<int>(out.size());
      out.emplace_back();
    }
    out[slot[r]].push_back(v);
  }
  return out;
}

std::vector<int> splice_candidates(const Pslg& p) {
  const auto inc = incidence(p);
  std::vector<int> out;
  for (int v = 0; v < static_cast<int>(p.vertices.size()); ++v)
    if (can_splice(p.segments, inc, v)) out.push_back(v);
  return out;
}

Pslg spliced(const Pslg& p, const std::vector<int>& vertices) {
  std::vector<Segment> segs = p.segments;
  std::vector<char> dead(segs.size(), 0);
  auto inc = incidence(p);
  std::vector<char> drop(p.vertices.size(), 0);
  auto unlink = [&](int v, int s) { inc[v].erase(std::find(inc[v].begin(), inc[v].end(), s)); };
  for (int v : vertices) {
    if (v < 0 || v >= static_cast<int>(inc.size()) || !can_splice(segs, inc, v)) continue;
    const int s0 = inc[v][0], s1 = inc[v][1];
    const int a = other_end(segs[s0], v), b = other_end(segs[s1], v);
    dead[s0] = dead[s1] = 1;
    unlink(a, s0);
    unlink(b, s1);
    inc[v].clear();
    const int joined = static_cast<int>(segs.size());
    segs.push_back({a, b, segs[s0].marker});
    dead.push_back(0);
    inc[a].push_back(joined);
    inc[b].push_back(joined);
    drop[v] = 1;
  }
  Pslg q = p;
  q.segments.clear();
  for (std::size_t s = 0; s < segs.size(); ++s)
    if (!dead[s]) q.segments.push_back(segs[s]);
  return without_vertices(q, drop);
}

std::optional<Pslg> rounded(const Pslg& p, int exponent) {
  const double g = std::ldexp(1.0, exponent);
  bool changed = false;
  auto snap = [&](Point& pt) {
    const Point r{std::nearbyint(pt.x / g) * g, std::nearbyint(pt.y / g) * g};
    if (r != pt && std::isfinite(r.x) && std::isfinite(r.y)) {
      pt = r;
      changed = true;
    }
  };
  Pslg q = p;
  for (Point& v : q.vertices) snap(v);
  for (Point& h : q.holes) snap(h);
  if (!changed) return std::nullopt;
  return q;
}

int extent_exponent(const Pslg& p) {
  if (p.vertices.empty()) return 0;
  double lox = p.vertices[0].x, hix = lox, loy = p.vertices[0].y, hiy = loy;
  for (const Point& v : p.vertices) {
    lox = std::min(lox, v.x), hix = std::max(hix, v.x);
    loy = std::min(loy, v.y), hiy = std::max(hiy, v.y);
  }
  const double extent = std::max(hix - lox, hiy - loy);
  if (!(extent > 0) || !std::isfinite(extent)) return 0;
  int e = 0;
  std::frexp(extent, &e);  // extent = m * 2^e with m in [0.5, 1): 2^e >= extent
  return e;
}

}  // namespace lepp::audit::detail
