// SPDX-License-Identifier: GPL-3.0-or-later
// The deviation catalogue's points (docs/CONFORMANCE.md, "Deviations";
// lepp/audit/deviations.h): computed exactly like the paper's choices on the
// same mesh, each tagged with its deviation (catalogue_points.cpp).
#pragma once
#include <vector>

#include "choice_points.h"

namespace lepp::audit::replay_detail {

// The catalogue's points at terminal edge l of t1 (t2 across it if has_t2).
// The paper's own choices are not excluded: a point that is one matches
// before the catalogue is asked. T: FH or CellTri. With `near` (the search around a
// point), the other reading's area centroid is left out where it is surely farther
// from *near than its tolerance (area_centroid_beyond): that search would drop it.
template <class T>
std::vector<Candidate> catalogue_points(const ReplayRules& rules, const T& t1, const T& t2, bool has_t2, int l,
                                        const Point* near = nullptr);

inline std::vector<Candidate> catalogue_points(const ReplayRules& rules, const Terminal& t) {
  return t.t2 == FH() ? catalogue_points(rules, t.t1, t.t1, false, t.l) : catalogue_points(rules, t.t1, t.t2, true, t.l);
}

// A bad triangle's own points: its circumcenter and off-center.
std::vector<Candidate> triangle_points(const ReplayRules& rules, FH f);

}  // namespace lepp::audit::replay_detail
