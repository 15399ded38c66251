// SPDX-License-Identifier: GPL-3.0-or-later
// Every resolution of exact length ties at the precision limit (ALGORITHM.md
// section 8b, "Every tie resolution"): the reference's own enumeration, in the
// order the fast engine's follows, so that both insert the same point.
#include <cstddef>
#include <set>
#include <stdexcept>
#include <utility>

#include "triangulation.h"

namespace lepp::reference::detail {
namespace {

class TieSearch {
 public:
  TieSearch(const Triangulation& tr, Method method, std::size_t max_states) : tr_(tr), method_(method), max_states_(max_states) {}

  bool run(FH t, Lepp& lepp, Selection& s) {
    path_ = {t};
    for (int e : tied_longest_edges(t))
      if (walk(t, e, lepp, s)) return true;
    return false;
  }
  bool cut() const { return cut_; }  // the bound left some state unseen

 private:
  // The Lepp goes on from f (the last face of path_) with edge i taken as its longest.
  bool walk(FH f, int i, Lepp& lepp, Selection& s) {
    if (max_states_ > 0 && seen_.size() >= max_states_) {
      cut_ = cut_ || seen_.count({ccw_ids(f), i}) == 0;  // never seen: the bound cut the search
      return false;
    }
    if (!seen_.insert({ccw_ids(f), i}).second) return false;
    if (f->is_constrained(i)) return terminal(f, i, FH(), lepp, s);
    FH n = f->neighbor(i);
    if (!n->info().in_domain) throw std::logic_error("reference: Lepp left the domain across an unconstrained edge");
    const int j = n->index(f);
    path_.push_back(n);
    for (int e : tied_longest_edges(n))
      if (e == j ? terminal(f, i, n, lepp, s) : walk(n, e, lepp, s)) return true;
    path_.pop_back();
    return false;
  }

  // A terminal edge reached: every pair of second-longest edges, t1's outer.
  bool terminal(FH t1, int edge, FH t2, Lepp& lepp, Selection& s) {
    Lepp alt;
    alt.t1 = t1, alt.t2 = t2, alt.edge = edge;
    const std::vector<int> none{-1};
    const std::vector<int> seconds1 = t2 == FH() ? none : tied_second_edges(t1, edge);
    const std::vector<int> seconds2 = t2 == FH() ? none : tied_second_edges(t2, t2->index(t1));
    for (int s1 : seconds1)
      for (int s2 : seconds2) {
        alt.s1 = s1, alt.s2 = s2;
        Selection choice = select_point(alt, method_);
        if (settle_selection(tr_, alt, method_, choice)) {
          alt.path = path_;
          lepp = std::move(alt);
          s = choice;
          return true;
        }
      }
    return false;
  }

  const Triangulation& tr_;
  Method method_;
  std::size_t max_states_;  // 0: no bound
  std::vector<FH> path_;  // t ... the current face
  std::set<std::pair<Tri, int>> seen_;
  bool cut_ = false;  // a state left unseen for the bound
};

}  // namespace

bool other_tie_resolution(const Triangulation& tr, FH t, Method method, std::size_t max_states, Lepp& lepp, Selection& s,
                          bool* cut) {
  TieSearch search(tr, method, max_states);
  const bool found = search.run(t, lepp, s);
  if (cut) *cut = !found && search.cut();
  return found;
}

}  // namespace lepp::reference::detail
