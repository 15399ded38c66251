// SPDX-License-Identifier: GPL-3.0-or-later
// Every resolution of exact length ties at the precision limit (ALGORITHM.md
// section 8b, "Every tie resolution"): the Lepps of a bad triangle and the
// second-longest edges of their terminal pairs under exact ties, in one fixed
// order, until a choice can be inserted. Cold: reached only when the edge order's
// Lepp has none. Independent of the certifier's enumeration, its oracle.
#include <cstddef>
#include <cstdint>
#include <unordered_set>
#include <vector>

#include "precision_stop.h"

namespace lepp::fast {
namespace {

// The edges of ti of maximal exact length, the edge order's longest first.
int tied_longest(const TriMesh& m, int ti, int out[3]) {
  const EdgeOrder order(m, ti);
  const EdgeRank r = order.rank();
  int n = 0;
  out[n++] = r.longest;
  if (order.same_length(r.longest, r.middle)) {
    out[n++] = r.middle;
    if (order.same_length(r.longest, r.shortest)) out[n++] = r.shortest;
  }
  return n;
}

// The second-longest edges of ti with edge e taken as its longest: the longer of
// the other two in the edge order, then the other one if their lengths tie.
int tied_second(const TriMesh& m, int ti, int e, int out[2]) {
  const EdgeOrder order(m, ti);
  int i = next3(e), j = prev3(e);
  if (order.longer(j, i)) std::swap(i, j);
  out[0] = i, out[1] = j;
  return order.same_length(i, j) ? 2 : 1;
}

class TieSearch {
 public:
  TieSearch(TriMesh& m, Method method, std::size_t max_states, SliverObstacles& obstacles)
      : m_(m), method_(method), max_states_(max_states), obstacles_(obstacles) {}

  bool run(int t, Lepp& lepp, Choice& c) {
    path_.assign(1, t);
    int cand[3];
    const int n = tied_longest(m_, t, cand);
    for (int k = 0; k < n; ++k)
      if (walk(t, cand[k], lepp, c)) return true;
    return false;
  }
  bool cut() const { return cut_; }  // the bound left some state unseen

 private:
  // The Lepp goes on from ti (path_'s last triangle) with edge e as its longest.
  bool walk(int ti, int e, Lepp& lepp, Choice& c) {
    const std::int64_t state = 3 * static_cast<std::int64_t>(ti) + e;
    if (max_states_ > 0 && seen_.size() >= max_states_) {
      cut_ = cut_ || seen_.count(state) == 0;  // a state never seen: the bound cut the search
      return false;
    }
    if (!seen_.insert(state).second) return false;
    const FTri& f = m_.t(ti);
    if (f.seg(e) >= 0 || f.nbr[e] < 0) return terminal(ti, e, -1, -1, lepp, c);  // constrained: one terminal triangle
    const int next = nbr_tri(f.nbr[e]), j = nbr_edge(f.nbr[e]);
    int cand[3];
    const int n = tied_longest(m_, next, cand);
    path_.push_back(next);
    for (int k = 0; k < n; ++k)
      if (cand[k] == j ? terminal(ti, e, next, j, lepp, c) : walk(next, cand[k], lepp, c)) return true;
    path_.pop_back();
    return false;
  }

  // A terminal edge reached: every pair of second-longest edges, t1's outer.
  bool terminal(int t1, int e1, int t2, int e2, Lepp& lepp, Choice& c) {
    Lepp alt;
    alt.t1 = t1, alt.e1 = e1, alt.t2 = t2, alt.e2 = e2;
    int s1[2] = {-1, -1}, s2[2] = {-1, -1};
    const int n1 = t2 < 0 ? 1 : tied_second(m_, t1, e1, s1), n2 = t2 < 0 ? 1 : tied_second(m_, t2, e2, s2);
    for (int i = 0; i < n1; ++i)
      for (int k = 0; k < n2; ++k) {
        alt.m1 = s1[i], alt.m2 = s2[k];
        Choice choice = select_point(m_, alt, method_);
        if (settle_choice(m_, alt, method_, choice, obstacles_)) {
          alt.path = path_;
          lepp = std::move(alt);
          c = choice;
          return true;
        }
      }
    return false;
  }

  TriMesh& m_;
  Method method_;
  std::size_t max_states_;  // 0: no bound
  SliverObstacles& obstacles_;
  std::vector<int> path_;  // t ... the current triangle
  std::unordered_set<std::int64_t> seen_;
  bool cut_ = false;  // a state left unseen for the bound
};

}  // namespace

bool other_tie_resolution(TriMesh& m, int t, Method method, std::size_t max_states, Lepp& lepp, Choice& c,
                          SliverObstacles& obstacles, bool* cut) {
  TieSearch search(m, method, max_states, obstacles);
  const bool found = search.run(t, lepp, c);
  if (cut) *cut = !found && search.cut();
  return found;
}

}  // namespace lepp::fast
