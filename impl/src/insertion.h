// SPDX-License-Identifier: GPL-3.0-or-later
// Inserting a Steiner point without point location (ALGORITHM.md section 6):
// split the constrained edge, the triangle or the terminal edge it lies on,
// then restore the constrained Delaunay property by Lawson flips that never
// cross a constrained edge.
#pragma once
#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "bad_queue.h"
#include "point_selection.h"
#include "predicates.h"
#include "tri_mesh.h"

namespace lepp::fast {

class Inserter {
 public:
  std::int64_t cocircular_ties = 0;

  // Inserts choice.point as vertex id pts.size(); returns a triangle with the new
  // vertex at v[0] (its star is walked from there) and the segment it split, or -1.
  // `at`: where the point lies, when the precision stop's test found it (else located here).
  int insert(TriMesh& m, SegmentMembership& mem, const Choice& choice, int& split_segment, Located at = {}) {
    const int p = static_cast<int>(m.pts.size());
    int made[4], count = 0;
    split_segment = -1;
    kept_ = -1;
    if (choice.edge >= 0) {
      split_segment = segment_of_edge(m, mem, choice.tri, choice.edge);
      const int keep = kept_side(m, choice.tri, choice.edge, choice.point);
      m.pts.push_back(choice.point);
      count = keep == 0 ? m.split_edge(choice.tri, choice.edge, p, 0, made)
                        : m.split_edge_keeping(choice.tri, choice.edge, p, keep > 0, made, kept_);
    } else {
      int where = choice.tri, edge = -1;
      if (at.tri >= 0) {
        where = at.tri, edge = at.edge;
      } else if (!locate_in(m, where, choice.point, edge) && edge == -2 && choice.other >= 0) {
        where = choice.other;
        locate_in(m, where, choice.point, edge);
      }
      if (edge == -2) throw std::logic_error("fast engine: Steiner point outside its terminal quad");
      if (edge == -3) throw std::logic_error("fast engine: Steiner point on an existing vertex");
      m.pts.push_back(choice.point);
      if (edge < 0) {
        m.split_triangle(where, p, made);
        count = 3;
      } else {
        const std::int8_t flag = m.t(where).seg(edge);
        if (flag >= 0) split_segment = segment_of_edge(m, mem, where, edge);
        count = m.split_edge(where, edge, p, flag, made);
      }
    }
    mem.add_steiner(split_segment);
    // Legalization order (ALGORITHM.md section 7, "creation order"): the initial
    // triangles (p, u, w) by increasing id of u, each legalized depth first.
    // (At most four, with distinct u: an insertion sort in place of std::sort's calls.)
    for (int i = 1; i < count; ++i) {
      const int x = made[i], u = m.t(x).v(1);
      int j = i;
      for (; j > 0 && m.t(made[j - 1]).v(1) > u; --j) made[j] = made[j - 1];
      made[j] = x;
    }
    created_.clear();
    for (int k = count; k-- > 0;) {
      stack_.push_back(made[k]);
      if (record_creation) created_.push_back(Item{made[count - 1 - k], 0});
      // The apex across each new link edge is the next thing the flips read.
      const int code = m.t(made[k]).nbr[0];
      if (code >= 0) __builtin_prefetch(&m.p(m.t(nbr_tri(code)).v(nbr_edge(code))));
    }
    if (record_creation)
      for (Item& it : created_) it.stamp = m.stamp[static_cast<std::size_t>(it.tri)];
    restore_delaunay(m);
    return made[0];
  }

  // The triangle the last insertion kept beside its sliver (ALGORITHM.md section
  // 6, "A split off its line"), or -1: not incident to the new point, so not in
  // its star, yet its edge ab is no longer constrained, so it joins the batch.
  int kept() const { return kept_; }

  // Record the triangles each insertion creates, in creation order (the flip order's batch).
  bool record_creation = false;
  // The last insertion's created triangles (slot and stamp), in creation order;
  // some no longer exist (a later flip of the same insertion destroyed them).
  const std::vector<Item>& created() const { return created_; }

 private:
  static int segment_of_edge(const TriMesh& m, const SegmentMembership& mem, int ti, int i) {
    const FTri& f = m.t(ti);
    return mem.segment_of(f.v(next3(i)), f.v(prev3(i)));
  }

  // A split of constrained edge i of ti = (c, a, b) at p strictly off the line ab
  // keeps the triangle on the side p moves away from when p lies strictly outside
  // its circumcircle (ALGORITHM.md section 6, "A split off its line"): the usual
  // split would leave the edge from p to that triangle's apex not locally
  // Delaunay, and no flip opposite p repairs it. 1: keep the neighbour across ab
  // (p on c's side), -1: keep ti (p beyond ab), 0: the usual split.
  static int kept_side(const TriMesh& m, int ti, int i, const Point& p) {
    const FTri& f = m.t(ti);
    const Point &c = m.p(f.v(i)), &a = m.p(f.v(next3(i))), &b = m.p(f.v(prev3(i)));
    const int side = orient(a, b, p);
    if (side > 0) {
      if (f.nbr[i] < 0) return 0;
      const FTri& g = m.t(nbr_tri(f.nbr[i]));
      return incircle(m.p(g.v(nbr_edge(f.nbr[i]))), b, a, p) < 0 ? 1 : 0;
    }
    if (side < 0) return incircle(c, a, b, p) < 0 ? -1 : 0;
    return 0;
  }

  // Where p lies in the closed triangle ti: edge = -1 strictly inside, 0..2 on
  // the interior of that edge, -2 outside, -3 on a vertex. Returns true if inside or on an edge.
  static bool locate_in(const TriMesh& m, int ti, const Point& p, int& edge) {
    const FTri& f = m.t(ti);
    int o[3];
    for (int i = 0; i < 3; ++i) o[i] = orient(m.p(f.v(next3(i))), m.p(f.v(prev3(i))), p);
    if (o[0] < 0 || o[1] < 0 || o[2] < 0) return edge = -2, false;
    int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
    if (zeros >= 2) return edge = -3, false;
    edge = zeros == 0 ? -1 : (o[0] == 0 ? 0 : o[1] == 0 ? 1 : 2);
    return true;
  }

  void restore_delaunay(TriMesh& m) {
    while (!stack_.empty()) {
      int ti = stack_.back();
      stack_.pop_back();
      const FTri& f = m.t(ti);
      if (f.seg(0) >= 0 || f.nbr[0] < 0) continue;  // never flip a constrained edge
      const FTri& g = m.t(nbr_tri(f.nbr[0]));
      // A flip rewrites the neighbour and bumps its stamp, cold in cache: fetch it
      // while the in-circle test runs (issue 40: a third of flip_edge0's time).
      __builtin_prefetch(&m.stamp[static_cast<std::size_t>(nbr_tri(f.nbr[0]))], 1);
      int s = incircle(m.p(f.v(0)), m.p(f.v(1)), m.p(f.v(2)), m.p(g.v(nbr_edge(f.nbr[0]))));
      if (s > 0) {
        int ni = m.flip_edge0(ti);  // ti = (p, u, d), then ni = (p, d, w): ti is legalized first
        if (record_creation) {
          created_.push_back(Item{ti, m.stamp[static_cast<std::size_t>(ti)]});
          created_.push_back(Item{ni, m.stamp[static_cast<std::size_t>(ni)]});
        }
        stack_.push_back(ni);
        stack_.push_back(ti);
      } else if (s == 0) {
        ++cocircular_ties;  // left as it is (ALGORITHM.md section 6)
      }
    }
  }

  std::vector<int> stack_;
  std::vector<Item> created_;
  int kept_ = -1;
};

}  // namespace lepp::fast
