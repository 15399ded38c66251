// SPDX-License-Identifier: GPL-3.0-or-later
// Lepp(t): the longest-edge propagating path to a terminal edge (ALGORITHM.md section 3).
#pragma once
#include <vector>

#include "edge_order.h"
#include "tri_mesh.h"

namespace lepp::fast {

struct Lepp {
  int t1 = -1, e1 = -1;  // terminal triangle reached, and its index of the terminal edge
  int t2 = -1, e2 = -1;  // the triangle across an unconstrained terminal edge, else -1
  // The second-longest edges of t1 and t2 where another resolution of an exact
  // length tie fixed them (the precision limit, tie_resolutions.cpp); -1: the edge order's.
  int m1 = -1, m2 = -1;
  std::vector<int> path;  // t ... t1 (then t2): reused between searches
};

// Fills `out` with Lepp(t). The path never crosses a constrained edge.
inline void lepp_search(TriMesh& m, int t, Lepp& out) {
  out.path.clear();
  out.t2 = out.e2 = out.m1 = out.m2 = -1;
  int cur = t;
  int e = longest_edge(m, cur);
  for (;;) {
    out.path.push_back(cur);
    const FTri& f = m.t(cur);
    if (f.seg(e) >= 0 || f.nbr[e] < 0) {  // constrained (or boundary, which is constrained)
      out.t1 = cur, out.e1 = e;
      return;
    }
    int next = nbr_tri(f.nbr[e]), j = nbr_edge(f.nbr[e]);
    int ne = longest_edge(m, next);
    if (ne == j) {  // e is the longest edge of both: terminal
      out.t1 = cur, out.e1 = e, out.t2 = next, out.e2 = j;
      out.path.push_back(next);
      return;
    }
    cur = next, e = ne;
  }
}

// The second-longest edge of t1 (t2 when second) of the Lepp's terminal pair.
inline int second_longest(TriMesh& m, const Lepp& lepp, bool second) {
  const int fixed = second ? lepp.m2 : lepp.m1;
  return fixed >= 0 ? fixed : middle_edge(m, second ? lepp.t2 : lepp.t1);
}

}  // namespace lepp::fast
