// SPDX-License-Identifier: GPL-3.0-or-later
// The cocircular cells of the replay's mesh (cocircular_cells.h).
#include "cocircular_cells.h"

#include <algorithm>
#include <set>

namespace lepp::audit::replay_detail {

bool in_domain(const Triangulation& tr, FH f) { return !tr.cdt.is_infinite(f) && f->info().in_domain; }

bool cocircular_edge(const Triangulation& tr, FH f, int i) {
  FH n = f->neighbor(i);
  if (f->is_constrained(i) || !in_domain(tr, f) || !in_domain(tr, n)) return false;
  return tr.cdt.side_of_oriented_circle(n, f->vertex(i)->point(), false) == CGAL::ON_ORIENTED_BOUNDARY;
}

int Cell::position(VH v) const {
  for (std::size_t k = 0; k < ring.size(); ++k)
    if (ring[k] == v) return static_cast<int>(k);
  return -1;
}

namespace {

// A cell of one triangle: f's vertices and edges as they are.
Cell single(const Triangulation& tr, FH f) {
  Cell c;
  c.region = f->info().region;
  for (int k = 0; k < 3; ++k) {
    // Side k runs from vertex k to vertex k+1: the edge opposite vertex k+2.
    int opposite = Cdt::cw(k);
    c.ring.push_back(f->vertex(k));
    c.side_constrained.push_back(f->is_constrained(opposite));
    FH n = f->neighbor(opposite);
    c.side_outside.push_back(!f->is_constrained(opposite) && in_domain(tr, n) ? n : FH());
  }
  return c;
}

}  // namespace

int CellMap::cell_of(FH f) {
  auto it = cell_of_.find(f);
  if (it != cell_of_.end()) return it->second;
  // The triangles joined to f by cocircular edges.
  std::vector<FH> faces{f};
  std::set<FH> member{f};
  for (std::size_t k = 0; k < faces.size(); ++k)
    for (int i = 0; i < 3; ++i) {
      FH n = faces[k]->neighbor(i);
      if (member.count(n) || !cocircular_edge(tr_, faces[k], i)) continue;
      member.insert(n);
      faces.push_back(n);
    }
  // Its boundary, walked counter-clockwise: each directed side keeps the cell on its left.
  struct Side {
    VH to;
    bool constrained;
    FH outside;
  };
  std::map<VH, Side> next;
  bool simple = true;
  for (FH g : faces)
    for (int i = 0; i < 3; ++i) {
      FH n = g->neighbor(i);
      if (member.count(n) && !g->is_constrained(i)) continue;
      VH a = g->vertex(Cdt::ccw(i)), b = g->vertex(Cdt::cw(i));
      bool constrained = g->is_constrained(i);
      simple = simple && next.emplace(a, Side{b, constrained, !constrained && in_domain(tr_, n) ? n : FH()}).second;
    }
  Cell cell;
  cell.region = f->info().region;
  if (simple && !next.empty()) {
    VH start = next.begin()->first, v = start;
    do {
      auto s = next.find(v);
      if (s == next.end() || cell.ring.size() > next.size()) break;
      cell.ring.push_back(v);
      cell.side_constrained.push_back(s->second.constrained);
      cell.side_outside.push_back(s->second.outside);
      v = s->second.to;
    } while (v != start);
    // A triangulated convex polygon of n vertices has n - 2 triangles.
    simple = v == start && cell.ring.size() == next.size() && cell.ring.size() == faces.size() + 2;
  }
  if (!simple) {
    // Not a polygon (cannot happen in a constrained Delaunay mesh): no freedom taken.
    for (FH g : faces) {
      cell_of_[g] = static_cast<int>(cells_.size());
      cells_.push_back(single(tr_, g));
    }
    return cell_of_[f];
  }
  int c = static_cast<int>(cells_.size());
  cells_.push_back(std::move(cell));
  for (FH g : faces) cell_of_[g] = c;
  return c;
}

CellTri CellMap::triangle(int c, int a, int b, int d) const {
  const Cell& cell = cells_[static_cast<std::size_t>(c)];
  const int n = static_cast<int>(cell.ring.size());
  CellTri t;
  t.cell = c;
  t.region = cell.region;
  t.pos = {a, b, d};
  for (int i = 0; i < 3; ++i) {
    t.v[static_cast<std::size_t>(i)] = cell.ring[static_cast<std::size_t>(t.pos[static_cast<std::size_t>(i)])];
    // Edge i runs from pos[i+1] to pos[i+2]: a side when they are consecutive.
    int from = t.pos[static_cast<std::size_t>(Cdt::ccw(i))], to = t.pos[static_cast<std::size_t>(Cdt::cw(i))];
    t.constrained[static_cast<std::size_t>(i)] = (from + 1) % n == to && cell.side_constrained[static_cast<std::size_t>(from)];
  }
  return t;
}

void CellMap::across(const CellTri& t, int i, std::vector<CellTri>& out) {
  const Cell& own = cells_[static_cast<std::size_t>(t.cell)];
  const int n = static_cast<int>(own.ring.size());
  const int from = t.pos[static_cast<std::size_t>(Cdt::ccw(i))], to = t.pos[static_cast<std::size_t>(Cdt::cw(i))];
  if ((from + 1) % n != to) {
    // A diagonal: any ring vertex strictly between from and to (counter-clockwise) is on its other side.
    for (int q = (from + 1) % n; q != to; q = (q + 1) % n) out.push_back(triangle(t.cell, to, from, q));
    return;
  }
  FH outside = own.side_outside[static_cast<std::size_t>(from)];
  if (own.side_constrained[static_cast<std::size_t>(from)] || outside == FH()) return;
  const VH a = own.ring[static_cast<std::size_t>(from)], b = own.ring[static_cast<std::size_t>(to)];
  const int d = cell_of(outside);
  const Cell& other = cells_[static_cast<std::size_t>(d)];
  const int m = static_cast<int>(other.ring.size());
  const int pb = other.position(b), pa = other.position(a);
  if (pa < 0 || pb < 0 || (pb + 1) % m != pa) return;  // not a side there (cannot happen)
  for (int q = (pa + 1) % m; q != pb; q = (q + 1) % m) out.push_back(triangle(d, pb, pa, q));
}

bool CellMap::overlap(const CellTri& a, const CellTri& b) const {
  if (a.cell != b.cell) return false;
  const int n = static_cast<int>(cells_[static_cast<std::size_t>(a.cell)].ring.size());
  std::array<int, 3> sa = a.pos, sb = b.pos;
  std::sort(sa.begin(), sa.end());
  std::sort(sb.begin(), sb.end());
  if (sa == sb) return true;
  // Points in convex position: two triangles overlap iff two of their edges cross.
  auto strictly_between = [n](int i, int j, int k) { return k != i && k != j && (k - i + n) % n < (j - i + n) % n; };
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y) {
      int i = a.pos[static_cast<std::size_t>(x)], j = a.pos[static_cast<std::size_t>((x + 1) % 3)];
      int k = b.pos[static_cast<std::size_t>(y)], l = b.pos[static_cast<std::size_t>((y + 1) % 3)];
      if (i == k || i == l || j == k || j == l) continue;
      if (strictly_between(i, j, k) != strictly_between(i, j, l)) return true;
    }
  return false;
}

namespace {

// Makes a-b an edge of the mesh by flipping, one at a time, the edge that
// a-b crosses next to a (each flip makes an edge at a, so the crossings drop
// by one). Only cocircular edges are flipped.
bool make_edge(Triangulation& tr, VH a, VH b, std::vector<EdgeIds>& flips) {
  for (std::size_t guard = 0; guard <= tr.cdt.number_of_vertices(); ++guard) {
    FH f;
    int i;
    if (tr.cdt.is_edge(a, b, f, i)) return true;
    const CPoint &pa = a->point(), &pb = b->point();
    FH cross;
    Cdt::Face_circulator fc = tr.cdt.incident_faces(a), done = fc;
    do {
      if (!in_domain(tr, fc)) continue;
      int k = fc->index(a);
      const CPoint &u = fc->vertex(Cdt::ccw(k))->point(), &w = fc->vertex(Cdt::cw(k))->point();
      if (static_cast<int>(CGAL::orientation(pa, pb, u)) * static_cast<int>(CGAL::orientation(pa, pb, w)) < 0 &&
          static_cast<int>(CGAL::orientation(u, w, pa)) * static_cast<int>(CGAL::orientation(u, w, pb)) < 0) {
        cross = fc;
        break;
      }
    } while (++fc != done);
    if (cross == FH()) return false;
    int k = cross->index(a);
    if (!cocircular_edge(tr, cross, k)) return false;
    FH n = cross->neighbor(k);
    VH apex = n->vertex(n->index(cross));
    tr.cdt.flip(cross, k);
    flips.push_back(edge_key(id(a), id(apex)));
  }
  return false;
}

}  // namespace

bool realize(Triangulation& tr, const CellMap& cells, const std::vector<CellTri>& want, std::vector<EdgeIds>& flips) {
  for (const CellTri& t : want) {
    const int n = static_cast<int>(cells.cell(t.cell).ring.size());
    if (n == 3) continue;
    for (int i = 0; i < 3; ++i) {
      int from = t.pos[static_cast<std::size_t>(Cdt::ccw(i))], to = t.pos[static_cast<std::size_t>(Cdt::cw(i))];
      if ((from + 1) % n == to) continue;  // a side: always there
      if (!make_edge(tr, t.v[static_cast<std::size_t>(Cdt::ccw(i))], t.v[static_cast<std::size_t>(Cdt::cw(i))], flips))
        return false;
    }
  }
  return true;
}

void undo_flips(Triangulation& tr, std::vector<EdgeIds>& flips) {
  for (auto it = flips.rbegin(); it != flips.rend(); ++it) {
    FH f;
    int i;
    if (tr.cdt.is_edge(tr.vertex.at(static_cast<std::size_t>(it->first)), tr.vertex.at(static_cast<std::size_t>(it->second)), f, i))
      tr.cdt.flip(f, i);
  }
  flips.clear();
}

}  // namespace lepp::audit::replay_detail
