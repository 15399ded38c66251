// SPDX-License-Identifier: GPL-3.0-or-later
// The batch order's rounds (ALGORITHM.md section 7, "batch"): the triangles a
// member of a round reads or changes (its region), and the marks that keep the
// members of one round apart, so that their insertions do not depend on one
// another (and could run at once).
#pragma once
#include <algorithm>
#include <cstdint>
#include <unordered_set>
#include <vector>

#include "bad_queue.h"
#include "point_selection.h"
#include "predicates.h"
#include "sliver_obstacles.h"
#include "precision_stop.h"
#include "tri_mesh.h"

namespace lepp::fast {

// A slot is touched in the current round when a member's region reserved it or
// an insertion of the round wrote it. Slots grow with the mesh; marks follow.
class RoundMarks {
 public:
  void begin_round() { ++round_; }
  bool touched(int ti) const {
    const auto i = static_cast<std::size_t>(ti);
    return i < mark_.size() && mark_[i] == round_;
  }
  void mark(int ti) {
    const auto i = static_cast<std::size_t>(ti);
    if (i >= mark_.size()) mark_.resize(std::max(i + 1, 2 * mark_.size()), 0);
    mark_[i] = round_;
  }

 private:
  std::vector<std::uint32_t> mark_;
  std::uint32_t round_ = 0;
};

// A choice a round can take as it is: insertable as computed, and not a split of
// a domain boundary edge rounded strictly outside the domain (the sliver clause
// reads vertices and segments beyond any region). Anything else waits until it
// can be the first member of a round, and closes that round.
inline bool plain_choice(TriMesh& m, const Lepp& lepp, const Choice& c, SliverObstacles& obstacles) {
  if (c.edge >= 0) {
    const FTri& f = m.t(c.tri);
    if (f.nbr[c.edge] < 0 && orient(m.p(f.v(next3(c.edge))), m.p(f.v(prev3(c.edge))), c.point) < 0) return false;
  }
  return choice_insertable(m, lepp, c, obstacles);
}

// The region of a plain choice beyond its Lepp: the cavity (the triangles holding
// the point, then across unconstrained edges every triangle whose circumcircle
// holds it, on the circle included: a superset of what the insertion's flips
// destroy) and its ring (the other triangles sharing an edge with the cavity).
// Appended to `region`; false as soon as one is touched.
inline constexpr std::size_t kScannedCavity = 32;  // larger cavities are hashed

inline bool cavity_and_ring(const TriMesh& m, const Choice& c, const RoundMarks& marks, std::vector<int>& region,
                            std::vector<int>& cavity) {
  cavity.clear();
  auto add = [&](int ti) {
    for (int x : cavity)
      if (x == ti) return;
    cavity.push_back(ti);
  };
  if (c.edge >= 0) {
    add(c.tri);
    if (const int n = m.t(c.tri).nbr[c.edge]; n >= 0) add(nbr_tri(n));
  } else {
    for (int ti : {c.tri, c.other}) {
      if (ti < 0) continue;
      const FTri& f = m.t(ti);
      int o[3];
      for (int i = 0; i < 3; ++i) o[i] = orient(m.p(f.v(next3(i))), m.p(f.v(prev3(i))), c.point);
      if (o[0] < 0 || o[1] < 0 || o[2] < 0) continue;  // not in this one: in the other
      add(ti);
      for (int i = 0; i < 3; ++i)
        if (o[i] == 0 && f.nbr[i] >= 0) add(nbr_tri(f.nbr[i]));  // on an unconstrained edge: both sides
      break;
    }
  }
  // Every neighbour of a triangle holding the point is in the cavity or in the ring:
  // a touched one decides before any in-circle test (most waiting triangles wait here).
  for (int ti : cavity) {
    if (marks.touched(ti)) return false;
    for (int i = 0; i < 3; ++i)
      if (const int n = m.t(ti).nbr[i]; n >= 0 && marks.touched(nbr_tri(n))) return false;
  }
  // Membership in the cavity: a scan while it is small, a hash set once it is large
  // (a fan's cavity can hold thousands of triangles, and a scan per neighbour would
  // make its flood quadratic).
  thread_local std::unordered_set<int> large;
  bool hashed = false;
  auto in_cavity = [&](int n) {
    if (hashed) return large.count(n) > 0;
    return std::find(cavity.begin(), cavity.end(), n) != cavity.end();
  };
  for (std::size_t k = 0; k < cavity.size(); ++k) {
    const int ti = cavity[k];
    if (marks.touched(ti)) return false;
    const FTri& f = m.t(ti);
    for (int i = 0; i < 3; ++i) {
      if (f.nbr[i] < 0) continue;
      const int n = nbr_tri(f.nbr[i]);
      if (in_cavity(n)) continue;
      const FTri& g = m.t(n);
      // Whether a triangle is in the cavity depends on it alone, so the ring and the
      // cavity are the same sets whichever way the flood reaches them.
      if (f.seg(i) < 0 && incircle(m.p(g.v(0)), m.p(g.v(1)), m.p(g.v(2)), c.point) >= 0) {
        cavity.push_back(n);
        if (hashed) {
          large.insert(n);
        } else if (cavity.size() > kScannedCavity) {
          hashed = true;
          large.clear();
          large.insert(cavity.begin(), cavity.end());
        }
      } else {
        if (marks.touched(n)) return false;
        region.push_back(n);
      }
    }
  }
  region.insert(region.end(), cavity.begin(), cavity.end());
  return true;
}

// The next round's queue (section 7, "batch"): the entries that wait, in this
// round's order (`waiting`, then the rest of the queue, round[rest, ...), which the
// round never read), then the members' batches in member order; each triangle
// once, at its first place, none that is gone. The rest holds each live triangle
// once and none of the waiting ones; a batch holds only the round's new triangles
// and, after a split off its line (section 6), the kept triangle, which is older
// than the round and may wait in the rest. So the rest is moved as it is, and read
// for the marks only when a member kept a triangle.
inline void next_round_queue(const TriMesh& m, const std::vector<Item>& round, std::size_t rest,
                             const std::vector<Item>& waiting, const std::vector<Keyed>& batches, bool kept,
                             RoundMarks& queued, std::vector<Item>& out) {
  queued.begin_round();
  out.clear();
  auto take = [&](const Item& it) {
    if (!still_there(m, it) || queued.touched(it.tri)) return;
    queued.mark(it.tri);
    out.push_back(it);
  };
  for (const Item& it : waiting) take(it);
  if (kept) {
    for (std::size_t i = rest; i < round.size(); ++i)
      if (still_there(m, round[i])) queued.mark(round[i].tri);
  }
  out.insert(out.end(), round.begin() + static_cast<std::ptrdiff_t>(rest), round.end());
  for (const Keyed& k : batches) take(k.item);
}

}  // namespace lepp::fast
