// SPDX-License-Identifier: GPL-3.0-or-later
// The replay's edge order: ties branched on instead of broken by ids. Any
// total order of the edges consistent with their lengths is allowed, so a
// triangle may have several longest (or second-longest) edges, and a Lepp
// several ends. The reference engine's order (reference/src/geometry.cpp) is
// one such total order, ties broken by vertex ids, as the fast engine's is:
// the differential tests compare those two, so this one stays apart. All three
// decide lengths exactly with the same predicate (double_predicates.h).
#pragma once
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <vector>

#include "cocircular_cells.h"
#include "double_predicates.h"  // reference/src: exact predicates on double coordinates

namespace lepp::audit::replay_detail {

// The rules read a triangle through these: a face of the mesh, or a triangle
// of a cocircular cell's other triangulations (cocircular_cells.h).
inline VH vtx(FH f, int i) { return f->vertex(i); }
inline VH vtx(const CellTri& t, int i) { return t.v[static_cast<std::size_t>(i)]; }
inline bool constrained(FH f, int i) { return f->is_constrained(i); }
inline bool constrained(const CellTri& t, int i) { return t.constrained[static_cast<std::size_t>(i)]; }

template <class T>
FT len2(const T& f, int i) {
  return CGAL::squared_distance(vtx(f, Cdt::ccw(i))->point(), vtx(f, Cdt::cw(i))->point());
}

// Squared length of edge i of f in doubles: a filter. The coordinates are
// doubles, so each of dx, dy, dx*dx, dy*dy and the sum is off by at most half
// an ulp: the result is within a relative 4 DBL_EPSILON of the exact value
// unless something underflowed or overflowed (checked by the caller).
template <class T>
double approx_len2(const T& f, int i) {
  const auto& a = vtx(f, Cdt::ccw(i))->point().approx();
  const auto& b = vtx(f, Cdt::cw(i))->point().approx();
  if (a.x().inf() != a.x().sup() || a.y().inf() != a.y().sup() || b.x().inf() != b.x().sup() ||
      b.y().inf() != b.y().sup())
    return std::numeric_limits<double>::quiet_NaN();  // not a double point: decide exactly
  double dx = a.x().inf() - b.x().inf(), dy = a.y().inf() - b.y().inf();
  return dx * dx + dy * dy;
}

// The double endpoints of edge i of f in p, q; false if a point is not a double.
template <class T>
bool double_edge(const T& f, int i, Point& p, Point& q) {
  const auto& a = vtx(f, Cdt::ccw(i))->point().approx();
  const auto& b = vtx(f, Cdt::cw(i))->point().approx();
  p = {a.x().inf(), a.y().inf()}, q = {b.x().inf(), b.y().inf()};
  return a.x().is_point() && a.y().is_point() && b.x().is_point() && b.y().is_point();
}

// Compares the lengths of edges i and j of f: filtered, exact when needed (on
// the doubles, double_predicates.h: lazy Epeck's Gmpq took minutes on ulp clusters).
template <class T>
CGAL::Comparison_result compare_len_exact(const T& f, int i, int j) {
  double li = approx_len2(f, i), lj = approx_len2(f, j), m = std::max(li, lj);
  if (std::isfinite(li) && std::isfinite(lj) && m > 1e-280 && std::abs(li - lj) > 16 * DBL_EPSILON * m)
    return li < lj ? CGAL::SMALLER : CGAL::LARGER;
  Point a, b, c, d;
  if (double_edge(f, i, a, b) && double_edge(f, j, c, d))
    return static_cast<CGAL::Comparison_result>(compare_squared_lengths(a, b, c, d));
  return CGAL::compare(len2(f, i), len2(f, j));
}

// The inexact-length variant: the Lepp's length comparisons count two squared
// lengths within 8 DBL_EPSILON (relative, exactly) of each other as a tie, the
// rounding a double computation of dx*dx + dy*dy may make on each side. Set
// around the searches that allow it (LengthTiesWithinRounding): the Lepp helpers
// here are free functions shared by the mesh's faces and the cells' triangles.
inline thread_local bool length_ties_within_rounding = false;

struct LengthTiesWithinRounding {
  bool saved = length_ties_within_rounding;
  explicit LengthTiesWithinRounding(bool on) { length_ties_within_rounding = on; }
  ~LengthTiesWithinRounding() { length_ties_within_rounding = saved; }
  LengthTiesWithinRounding(const LengthTiesWithinRounding&) = delete;
  LengthTiesWithinRounding& operator=(const LengthTiesWithinRounding&) = delete;
};

// The comparison the Lepp reads: exact, or with near ties (above) as ties. The
// filter decides only beyond 16 DBL_EPSILON, outside that band.
template <class T>
CGAL::Comparison_result compare_len(const T& f, int i, int j) {
  const CGAL::Comparison_result r = compare_len_exact(f, i, j);
  if (r == CGAL::EQUAL || !length_ties_within_rounding) return r;
  const FT a = len2(f, i), b = len2(f, j);
  return CGAL::abs(a - b) <= FT(8 * DBL_EPSILON) * CGAL::max(a, b) ? CGAL::EQUAL : r;
}

template <class T>
bool is_longest(const T& f, int i) {
  return compare_len(f, i, Cdt::ccw(i)) != CGAL::SMALLER && compare_len(f, i, Cdt::cw(i)) != CGAL::SMALLER;
}

// Indices of the edges of f of maximal length (several on ties).
template <class T>
std::vector<int> longest_edges(const T& f) {
  std::vector<int> out;
  for (int i = 0; i < 3; ++i)
    if (is_longest(f, i)) out.push_back(i);
  return out;
}

// The second-longest edges of f when edge l is its longest: the longer of the
// other two, both on a tie.
template <class T>
std::vector<int> second_longest_given(const T& f, int l) {
  int j = Cdt::ccw(l), k = Cdt::cw(l);
  CGAL::Comparison_result r = compare_len(f, j, k);
  if (r == CGAL::LARGER) return {j};
  if (r == CGAL::SMALLER) return {k};
  return {j, k};
}

// The index in g of its vertex that is not a or b (the edge a-b is g's edge of that index).
template <class T>
int index_off(const T& g, VH a, VH b) {
  for (int i = 0; i < 3; ++i)
    if (vtx(g, i) != a && vtx(g, i) != b) return i;
  return -1;
}

}  // namespace lepp::audit::replay_detail
