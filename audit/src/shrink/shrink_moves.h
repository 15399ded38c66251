// SPDX-License-Identifier: GPL-3.0-or-later
// The edits the greedy shrinker tries on a PSLG (private to lepp_audit). Each
// returns a smaller or simpler PSLG, not yet validated: the shrinker validates
// it and asks the engine whether it still fails. The edits that matter for a
// polygon keep it closed: a boundary vertex is spliced out (its two segments
// become one), never just dropped, which would open the boundary and leave an
// empty domain.
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

#include "lepp/pslg.h"

namespace lepp::audit::detail {

// Drops the flagged vertices and every segment at them; ids renumbered,
// vertex markers kept for the others.
Pslg without_vertices(const Pslg& p, const std::vector<char>& drop);

// The connected pieces of the PSLG (vertices joined by segments, an isolated
// vertex is a piece of its own), each as the list of its vertices, ordered by
// their smallest vertex id.
std::vector<std::vector<int>> pieces(const Pslg& p);

// Vertices with exactly two segments, to two different neighbours that no
// segment joins yet: splicing one out keeps a polygon or a chain unbroken.
std::vector<int> splice_candidates(const Pslg& p);

// Splices out the given vertices in turn: the two segments at each become one
// segment between its neighbours, carrying the first segment's marker. A vertex
// that is no longer a candidate when its turn comes (an earlier splice joined
// its neighbours) is left alone.
Pslg spliced(const Pslg& p, const std::vector<int>& vertices);

// Every coordinate (vertices and hole points) rounded to the nearest multiple
// of 2^exponent (exact in doubles); nullopt when nothing changes.
std::optional<Pslg> rounded(const Pslg& p, int exponent);

// The exponent of the smallest power of two at least the largest extent of the
// vertices' bounding box (0 when there are no vertices).
int extent_exponent(const Pslg& p);

}  // namespace lepp::audit::detail
