// SPDX-License-Identifier: GPL-3.0-or-later
// The replay's three searches where its mesh may differ from the
// implementation's only in cocircular cells (the constrained Delaunay mesh is
// not unique there): any triangulation of the cells near the point
// (cocircular_cells.h), one or two cocircular flips near it or where recent
// insertions met ties, and CGAL's perturbed tie rule from then on.
#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include "distance_filter.h"
#include "replayer.h"

namespace lepp::audit::replay_detail {

namespace {

// Smallest angle below theta (exactly: sin^2 compared as in geometry.cpp's
// is_skinny, at the vertex opposite a shortest edge).
bool skinny(const CellTri& t, const FT& sin2) {
  int i = 0;
  for (int k = 1; k < 3; ++k)
    if (compare_len_exact(t, k, i) == CGAL::SMALLER) i = k;
  const CPoint& o = vtx(t, i)->point();
  K::Vector_2 u = vtx(t, Cdt::ccw(i))->point() - o, v = vtx(t, Cdt::cw(i))->point() - o;
  FT cross = u.x() * v.y() - u.y() * v.x();
  return cross * cross < sin2 * u.squared_length() * v.squared_length();
}

bool too_big(const CellTri& t, const FT& twice_max_area) {
  const CPoint &a = vtx(t, 0)->point(), &b = vtx(t, 1)->point(), &c = vtx(t, 2)->point();
  FT cross = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
  return CGAL::abs(cross) > twice_max_area;
}

// p in the closed triangle t or near it (a loose test in doubles, coordinates
// scaled by a power of two: only a filter before the exact distance tests).
bool near_triangle(const CellTri& t, const Point& p) {
  double m = std::max(std::abs(p.x), std::abs(p.y));
  std::array<Point, 3> q;
  for (int i = 0; i < 3; ++i) {
    q[static_cast<std::size_t>(i)] = {CGAL::to_double(vtx(t, i)->point().x()), CGAL::to_double(vtx(t, i)->point().y())};
    m = std::max({m, std::abs(q[static_cast<std::size_t>(i)].x), std::abs(q[static_cast<std::size_t>(i)].y)});
  }
  if (!(m > 0) || !std::isfinite(m)) return true;
  int e = 0;
  std::frexp(m, &e);
  const double px = std::ldexp(p.x, -e), py = std::ldexp(p.y, -e);
  for (int i = 0; i < 3; ++i) {
    const Point &u = q[static_cast<std::size_t>(i)], &v = q[static_cast<std::size_t>((i + 1) % 3)];
    const double ux = std::ldexp(u.x, -e), uy = std::ldexp(u.y, -e), dx = std::ldexp(v.x, -e) - ux, dy = std::ldexp(v.y, -e) - uy;
    if ((dx * (py - uy) - dy * (px - ux)) < -1e-9 * std::hypot(dx, dy) - 1e-300) return false;
  }
  return true;
}

std::array<int, 3> tri_key(const CellTri& t) {
  std::array<int, 3> k{{id(t.v[0]), id(t.v[1]), id(t.v[2])}};
  std::sort(k.begin(), k.end());
  return k;
}

}  // namespace

bool Replayer::maybe_bad(const CellTri& t) const {
  if (skinny(t, sin2_) || (threshold_within_rounding_ && skinny(t, sin2_rounding_))) return true;
  const std::optional<FT>& b = bound(t.region);
  return b && too_big(t, *b);
}

bool Replayer::match_cocircular(const Point& p, ReplayChoice& out) {
  if (match_any_triangulation(p, out)) return true;
  // Only when the search of the cells ran out of budget, or at a point that
  // is no choice (where the check ends): the older, narrower searches.
  if (match_local_flips(p, out)) return true;
  if (!perturbed_) {
    std::int64_t flips = perturbed_lawson({});
    if (flips > 0) {
      perturbed_ = true;
      cocircular_flips_ += flips;
      if (match_here(p, out) || match_local_flips(p, out)) return true;
    }
  }
  return false;
}

bool Replayer::find_edge(const EdgeIds& e, FH& f, int& i) const {
  return tr.cdt.is_edge(tr.vertex.at(static_cast<std::size_t>(e.first)), tr.vertex.at(static_cast<std::size_t>(e.second)), f, i);
}

// Flips a cocircular edge; returns the new edge (the other diagonal).
EdgeIds Replayer::flip(FH f, int i) {
  EdgeIds other = edge_key(id(f->vertex(i)), id(f->neighbor(i)->vertex(f->neighbor(i)->index(f))));
  tr.cdt.flip(f, i);
  return other;
}

// The cocircular edges where the replay's mesh may differ from the
// implementation's: around p, and where recent insertions met ties.
std::vector<EdgeIds> Replayer::flip_candidates(const Point& p) {
  std::vector<EdgeIds> out;
  std::set<EdgeIds> seen;
  auto consider = [&](FH f, int i) {
    if (!cocircular(f, i)) return;
    EdgeIds e = edge_key(id(f->vertex(Cdt::ccw(i))), id(f->vertex(Cdt::cw(i))));
    if (e.first >= 0 && seen.insert(e).second) out.push_back(e);
  };
  bool at_vertex = false;
  for (FH f : faces_near(p, at_vertex))
    for (int i = 0; i < 3; ++i) {
      consider(f, i);
      FH n = f->neighbor(i);
      if (in_domain(n))
        for (int j = 0; j < 3; ++j) consider(n, j);
    }
  for (auto it = recent_ties_.rbegin(); it != recent_ties_.rend(); ++it) {
    FH f;
    int i;
    if (find_edge(*it, f, i)) consider(f, i);
  }
  return out;
}

// Lawson flips with CGAL's symbolically perturbed in-circle test, from the
// given edges (all domain edges if empty) until none applies: the result is
// the constrained Delaunay triangulation CGAL's own insertion builds, which
// breaks every cocircular tie by the perturbation. Only cocircular edges of
// a Delaunay mesh flip, so the mesh stays constrained Delaunay.
std::int64_t Replayer::perturbed_lawson(std::vector<std::pair<FH, int>> todo) {
  if (todo.empty())
    for (FH f : tr.cdt.finite_face_handles())
      if (in_domain(f))
        for (int i = 0; i < 3; ++i) todo.push_back({f, i});
  std::int64_t flips = 0;
  while (!todo.empty()) {
    auto [f, i] = todo.back();
    todo.pop_back();
    if (!in_domain(f) || f->is_constrained(i)) continue;
    FH n = f->neighbor(i);
    if (!in_domain(n)) continue;
    if (tr.cdt.side_of_oriented_circle(n, f->vertex(i)->point(), true) != CGAL::ON_POSITIVE_SIDE) continue;
    tr.cdt.flip(f, i);
    ++flips;
    for (int k = 0; k < 3; ++k) todo.push_back({f, k}), todo.push_back({n, k});
  }
  return flips;
}

// ---- any triangulation of the cocircular cells (cocircular_cells.h) ----
//
// The same search as match_here, over the triangles that some
// triangulation of each cell has instead of the faces of the mesh: the
// terminal configurations whose quad holds p, then backwards along the Lepp
// tree to a bad triangle, keeping the triangles of one path pairwise
// compatible (no two overlapping in one cell). A path found is made real by
// flipping cocircular diagonals in its cells (the mesh stays constrained
// Delaunay), and match_here confirms it on the mesh. Bounded: at most
// rules.cocircular_search_budget triangles are looked at.

bool Replayer::spend(std::size_t& used) {
  if (++used <= rules.cocircular_search_budget) return true;
  search_exhausted_ = true;
  return false;
}

// Backwards from t (exit edge l; other the triangle across it, if any) to a
// bad triangle: the path from it to t, empty if none.
std::vector<CellTri> Replayer::cell_bad_reaching(CellMap& cells, const CellTri& t, int l, const CellTri* other, std::size_t& used) {
  std::vector<PathNode> nodes{{t, l, -1}};
  std::set<std::array<int, 3>> seen{tri_key(t)};
  if (other) seen.insert(tri_key(*other));
  std::vector<CellTri> across;
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    if (maybe_bad(nodes[k].t)) {
      std::vector<CellTri> path;
      for (int j = static_cast<int>(k); j >= 0; j = nodes[static_cast<std::size_t>(j)].next)
        path.push_back(nodes[static_cast<std::size_t>(j)].t);
      return path;
    }
    for (int e = 0; e < 3; ++e) {
      const CellTri f = nodes[k].t;
      if (e == nodes[k].exit || constrained(f, e)) continue;
      across.clear();
      cells.across(f, e, across);
      for (const CellTri& g : across) {
        if (!spend(used)) return {};
        if (seen.count(tri_key(g))) continue;
        int ge = index_off(g, vtx(f, Cdt::ccw(e)), vtx(f, Cdt::cw(e)));
        if (!is_longest(g, ge)) continue;
        bool fits = !(other && cells.overlap(g, *other));
        for (int j = static_cast<int>(k); fits && j >= 0; j = nodes[static_cast<std::size_t>(j)].next)
          fits = !cells.overlap(g, nodes[static_cast<std::size_t>(j)].t);
        if (!fits) continue;
        seen.insert(tri_key(g));
        nodes.push_back({g, ge, static_cast<int>(k)});
      }
    }
  }
  return {};
}

// A terminal configuration of some triangulation (t2 null: l constrained):
// when one of its choices is p and a bad triangle's Lepp reaches it, the
// mesh is flipped to have it and match_here decides.
bool Replayer::try_cell_terminal(CellMap& cells, const CellTri& t1, const CellTri* t2, int l, const Point& p, ReplayChoice& out,
                                 std::size_t& used) {
  for (const Candidate& c : t2 ? candidates(t1, *t2, true, l) : candidates(t1, t1, false, l)) {
    const double tol = tolerance(c.scale);
    if (surely_farther(p, c.point, tol) || distance(p, c) > tol) continue;
    std::vector<CellTri> path = cell_bad_reaching(cells, t1, l, t2, used);
    if (path.empty() && t2) path = cell_bad_reaching(cells, *t2, index_off(*t2, vtx(t1, Cdt::ccw(l)), vtx(t1, Cdt::cw(l))), &t1, used);
    if (path.empty()) continue;
    if (t2) path.push_back(path.back().v == t1.v ? *t2 : t1);
    std::vector<EdgeIds> flips;
    if (realize(tr, cells, path, flips) && match_here(p, out)) {
      cocircular_flips_ += static_cast<std::int64_t>(flips.size());
      return true;
    }
    undo_flips(tr, flips);  // cannot happen: the path's triangles fit in one triangulation
  }
  return false;
}

bool Replayer::match_any_triangulation(const Point& p, ReplayChoice& out) {
  bool at_vertex = false;
  std::vector<FH> near = faces_near(p, at_vertex);
  if (at_vertex) return false;
  CellMap cells(tr);
  std::set<int> near_cells;
  for (FH f : near) near_cells.insert(cells.cell_of(f));
  std::size_t used = 0;
  std::set<std::array<int, 4>> tried;  // terminal configurations by vertex ids
  std::vector<CellTri> across;
  for (int c : near_cells) {
    const int n = static_cast<int>(cells.cell(c).ring.size());
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b)
        for (int d = b + 1; d < n; ++d) {
          if (!spend(used)) return false;
          const CellTri t = cells.triangle(c, a, b, d);
          if (!near_triangle(t, p)) continue;
          // t holds p: it is t1 or t2 of the configuration, the other across a longest edge of both.
          for (int l : longest_edges(t)) {
            if (constrained(t, l)) {
              std::array<int, 4> key{{id(vtx(t, Cdt::ccw(l))), id(vtx(t, Cdt::cw(l))), id(vtx(t, l)), -1}};
              if (tried.insert(key).second && try_cell_terminal(cells, t, nullptr, l, p, out, used)) return true;
              continue;
            }
            across.clear();
            cells.across(t, l, across);
            for (const CellTri& u : across) {
              if (!spend(used)) return false;
              int ul = index_off(u, vtx(t, Cdt::ccw(l)), vtx(t, Cdt::cw(l)));
              if (!is_longest(u, ul)) continue;
              // The terminal edge, then the two apexes.
              std::array<int, 4> key{{id(vtx(t, Cdt::ccw(l))), id(vtx(t, Cdt::cw(l))), id(vtx(t, l)), id(vtx(u, ul))}};
              std::sort(key.begin(), key.begin() + 2);
              std::sort(key.begin() + 2, key.end());
              if (tried.insert(key).second && try_cell_terminal(cells, t, &u, l, p, out, used)) return true;
            }
          }
        }
  }
  return false;
}

bool Replayer::match_local_flips(const Point& p, ReplayChoice& out) {
  std::vector<EdgeIds> cands = flip_candidates(p);
  if (cands.empty()) return false;
  std::size_t attempts = 0;
  for (std::size_t a = 0; a < cands.size(); ++a) {
    FH f;
    int i;
    if (!find_edge(cands[a], f, i) || !cocircular(f, i)) continue;
    EdgeIds fa = flip(f, i);
    if (match_here(p, out)) {
      ++cocircular_flips_;
      return true;
    }
    for (std::size_t b = a + 1; b < cands.size() && attempts < 400; ++b, ++attempts) {
      FH g;
      int j;
      if (!find_edge(cands[b], g, j) || !cocircular(g, j)) continue;
      EdgeIds fb = flip(g, j);
      if (match_here(p, out)) {
        cocircular_flips_ += 2;
        return true;
      }
      if (find_edge(fb, g, j)) flip(g, j);
    }
    if (find_edge(fa, f, i)) flip(f, i);
  }
  return false;
}

// After an insertion: the edges opposite v whose quads are cocircular (the
// Lawson flips met a tie there).
void Replayer::record_ties(VH v) {
  Cdt::Face_circulator fc = tr.cdt.incident_faces(v), done = fc;
  do {
    if (in_domain(fc)) {
      int i = fc->index(v);
      if (cocircular(fc, i)) recent_ties_.push_back(edge_key(id(fc->vertex(Cdt::ccw(i))), id(fc->vertex(Cdt::cw(i)))));
    }
  } while (++fc != done);
  if (recent_ties_.size() > 32) recent_ties_.erase(recent_ties_.begin(), recent_ties_.end() - 32);
}

}  // namespace lepp::audit::replay_detail
