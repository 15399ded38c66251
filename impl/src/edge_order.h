// SPDX-License-Identifier: GPL-3.0-or-later
// The total edge order of ALGORITHM.md section 3: (squared length, -min id,
// -max id), squared lengths compared exactly.
#pragma once
#include <algorithm>

#include "predicates.h"
#include "tri_mesh.h"

namespace lepp::fast {

// A triangle's edges (by index: edge i is opposite v[i]) in edge order.
struct EdgeRank {
  int longest, middle, shortest;
};

class EdgeOrder {
 public:
  EdgeOrder(const TriMesh& mesh, int ti) : m_(mesh), f_(mesh.t(ti)) {
    for (int i = 0; i < 3; ++i) len_[i] = sqlen(a(i), b(i));
  }
  // True iff edge i is longer than edge j in the edge order.
  bool longer(int i, int j) const {
    int s = compare_sqlen(a(i), b(i), len_[i], a(j), b(j), len_[j]);
    if (s != 0) return s > 0;
    int mi = std::min(f_.v(next3(i)), f_.v(prev3(i))), mj = std::min(f_.v(next3(j)), f_.v(prev3(j)));
    if (mi != mj) return mi < mj;  // older vertices win ties
    return std::max(f_.v(next3(i)), f_.v(prev3(i))) < std::max(f_.v(next3(j)), f_.v(prev3(j)));
  }
  // True iff edges i and j have exactly the same length (a tie the ids decide).
  bool same_length(int i, int j) const { return compare_sqlen(a(i), b(i), len_[i], a(j), b(j), len_[j]) == 0; }
  int longest() const {
    int w = longer(0, 1) ? 0 : 1;
    return longer(w, 2) ? w : 2;
  }
  EdgeRank rank() const {
    int e[3] = {0, 1, 2};
    if (longer(e[1], e[0])) std::swap(e[0], e[1]);
    if (longer(e[2], e[1])) {
      std::swap(e[1], e[2]);
      if (longer(e[1], e[0])) std::swap(e[0], e[1]);
    }
    return {e[0], e[1], e[2]};
  }
  double sqlen_of(int i) const { return len_[i]; }

 private:
  const Point& a(int i) const { return m_.p(f_.v(next3(i))); }
  const Point& b(int i) const { return m_.p(f_.v(prev3(i))); }
  const TriMesh& m_;
  const FTri& f_;
  double len_[3];
};

// The longest edge of ti, computed once per triangle and cached in it, but for
// while the batch order's selection runs Lepp searches on several threads
// (TriMesh::cache_longest false): the cache shares a word with a vertex id the
// other threads read, so only the one thread that writes the mesh fills it.
inline int longest_edge(TriMesh& m, int ti) {
  FTri& f = m.t(ti);
  int l = f.longest();
  if (l < 0) {
    l = EdgeOrder(m, ti).longest();
    if (m.cache_longest) f.set_longest(l);
  }
  return l;
}

// The second-longest edge of ti: the other two edges' lengths alone (EdgeOrder
// computes all three), the edge order's ids only for an exact tie.
inline int middle_edge(TriMesh& m, int ti) {
  const int l = longest_edge(m, ti), i = next3(l), j = prev3(l);
  const FTri& f = m.t(ti);
  const Point &ai = m.p(f.v(next3(i))), &bi = m.p(f.v(prev3(i))), &aj = m.p(f.v(next3(j))), &bj = m.p(f.v(prev3(j)));
  const int s = compare_sqlen(ai, bi, sqlen(ai, bi), aj, bj, sqlen(aj, bj));
  if (s != 0) return s > 0 ? i : j;
  return EdgeOrder(m, ti).longer(i, j) ? i : j;
}

}  // namespace lepp::fast
