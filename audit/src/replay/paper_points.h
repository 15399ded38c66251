// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's choices at a terminal configuration, exactly and under every
// resolution of ties (paper_points.cpp).
#pragma once
#include <vector>

#include "choice_points.h"

namespace lepp::audit::replay_detail {

// Every point the paper's rule allows for terminal edge l of t1 and t2 across
// it if has_t2 (else l is constrained and t2 is not read). T: FH or CellTri.
template <class T>
std::vector<Candidate> paper_candidates(const ReplayRules& rules, const T& t1, const T& t2, bool has_t2, int l);

inline std::vector<Candidate> paper_candidates(const ReplayRules& rules, const Terminal& t) {
  return t.t2 == FH() ? paper_candidates(rules, t.t1, t.t1, false, t.l) : paper_candidates(rules, t.t1, t.t2, true, t.l);
}

}  // namespace lepp::audit::replay_detail
