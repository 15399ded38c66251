// SPDX-License-Identifier: GPL-3.0-or-later
// The precision-limit exemption for any mesher (docs/CERTIFIER.md section 5c):
// a triangle below theta is exempt when every point the paper's Select Point
// allows for it (every Lepp under every resolution of equal lengths, every
// branch) rounds, in every way a mesher may round it, to a point that cannot be
// inserted. Reads only the mesh (and which of its edges lie on segment chains).
// Private to the certifier.
#pragma once
#include <chrono>
#include <cstddef>
#include <optional>
#include <vector>

#include "lepp/boundary_sliver.h"
#include "lepp/certify.h"
#include "lepp/mesh.h"
#include "lepp/refine.h"
#include "lepp/rounding.h"
#include "unwritten.h"

namespace lepp::certify {

// The mesh as the certifier has checked it. Half-edge h = 3t + i runs from
// triangle t's vertex i to vertex i + 1; twin[h] is the opposite half-edge, -1
// on the mesh boundary, -2 for a bad edge; chain[h] is 1 on a segment chain.
// outside: the input's vertices and segments outside the expected domain, and
// chains: the mesh's segment-chain edges (the sliver clause of a boundary split,
// ALGORITHM.md section 8b: the domain's own boundary blocks it too).
struct PrecisionView {
  const Mesh& mesh;
  const std::vector<char>& tri_ok;
  const UnwrittenVector<int>& twin;
  const std::vector<char>& chain;
  const OutsideInput& outside;
  const OutsideInput& chains;
};

// How far a search may go: Lepp states per triangle (0: no bound), and a deadline.
// ties_by_ids: equal lengths decided by vertex ids as lepp's edge order does
// (Options::precision_ties_by_ids, for meshes of older lepp versions), else every tie.
struct PrecisionLimits {
  std::size_t states = kTieSearchStates;
  std::optional<std::chrono::steady_clock::time_point> deadline;
  bool ties_by_ids = false;
};

// Whether triangle t is precision-limited for `method`: Exempt when each choice of
// point is, at every rounding (the engines' formula of ALGORITHM.md section 5 and
// both directed roundings of each coordinate of the exact point), not insertable in
// the sense of ALGORITHM.md section 8b; Rejected when one is (the first found, in the
// search's order, is the witness); Undecided when the search stopped at its bound of
// Lepp states, at the deadline, or met a bad triangle or edge before deciding. Only
// Exempt exempts. The claim's triangle is t.
PrecisionClaim precision_claim(const PrecisionView& view, std::size_t t, Method method, const PrecisionLimits& limits);

}  // namespace lepp::certify
