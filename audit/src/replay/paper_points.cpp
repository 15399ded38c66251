// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's choices at a terminal configuration: the rows of the paper's
// table (reference/src/paper_choices.h, the one definition Select Point shares)
// evaluated exactly, for every pair of second-longest edges a tie allows, with
// both branches of Remark 10 within the point tolerance of the other
// triangle's boundary.
#include "paper_points.h"

#include "paper_choices.h"  // reference/src: the paper's table

namespace lepp::audit::replay_detail {

template <class T>
std::vector<Candidate> paper_candidates(const ReplayRules& rules, const T& t1, const T& t2, bool has_t2, int l) {
  std::vector<Candidate> out;
  if (!has_t2) {
    for (const PaperOption& o : paper_options(rules.method, false, false, false)) out.push_back(midpoint(o.rule, t1, l));
    return out;
  }
  VH a = vtx(t1, Cdt::ccw(l)), b = vtx(t1, Cdt::cw(l));
  int l2 = index_off(t2, a, b);
  std::vector<int> S1 = second_longest_given(t1, l), S2 = second_longest_given(t2, l2);
  auto centroid = [&](Rule rule) { return quad_centroid(rule, t1, t2, l, rules.centroid); };
  for (int s1 : S1) {
    for (int s2 : S2) {
      bool c1 = constrained(t1, s1), c2 = constrained(t2, s2);
      for (const PaperOption& o : paper_options(rules.method, true, c1, c2)) {
        if (o.when != PaperCondition::Always) {
          // Remark 10: the centroid tested in the triangle other than t*; within
          // the point tolerance of its boundary, both branches. A flat quad has
          // no area centroid: not inside, so the midpoint.
          const T& other = o.triangle == 1 ? t2 : t1;
          std::optional<Candidate> g = centroid(Rule::CentroidInOther);
          int inside = g ? inside_status(other, *g, point_tolerance(rules, g->scale)) : -1;
          const bool holds = o.when == PaperCondition::CentroidInsideOther ? inside >= 0 : inside <= 0;
          if (!holds) continue;
        }
        if (o.point == PaperPoint::TerminalEdgeMidpoint) {
          out.push_back(midpoint(o.rule, t1, l));
        } else if (o.point == PaperPoint::SecondLongestMidpoint) {
          out.push_back(o.triangle == 1 ? midpoint(o.rule, t1, s1) : midpoint(o.rule, t2, s2));
        } else if (std::optional<Candidate> g = centroid(o.rule)) {
          out.push_back(*g);
        }
      }
    }
  }
  return out;
}

template std::vector<Candidate> paper_candidates(const ReplayRules&, const FH&, const FH&, bool, int);
template std::vector<Candidate> paper_candidates(const ReplayRules&, const CellTri&, const CellTri&, bool, int);

}  // namespace lepp::audit::replay_detail
