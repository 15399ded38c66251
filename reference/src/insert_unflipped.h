// SPDX-License-Identifier: GPL-3.0-or-later
// The reference's insertion without its Lawson flips, for the audit's replay of a
// program whose mesh is not the constrained Delaunay one (docs/CONFORMANCE.md,
// "The program's mesh"): no flips at all, or flips it decides itself. A header of
// its own so that triangulation.h, included by every unit of the reference, stays as it is.
#pragma once
#include "triangulation.h"

namespace lepp::reference::detail {

// insert_point (triangulation.h) up to the flips: the point inserted (a split of
// s's constrained edge, or into the face holding it), ids, segments, domain flags
// and the kept triangle beside a sliver set; no flip made. insert_point is this
// followed by the Lawson flips of ALGORITHM.md section 7.
VH insert_point_unflipped(Triangulation& tr, const Selection& s, FH t1, FH* kept = nullptr);

}  // namespace lepp::reference::detail
