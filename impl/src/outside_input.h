// SPDX-License-Identifier: GPL-3.0-or-later
// The input outside the domain, for the sliver clause of the precision stop
// (ALGORITHM.md section 8b): the fast engine keeps no triangles there, so a
// boundary split whose rounded midpoint falls strictly outside the domain is
// checked against the PSLG's own vertices and segments that no domain triangle
// has. Computed on first use (one pass over the triangles): only that rare
// branch asks, so the common path never pays for it.
#pragma once
#include "lepp/boundary_sliver.h"
#include "lepp/pslg.h"
#include "tri_mesh.h"

namespace lepp::fast {

class OutsideOfDomain {
 public:
  OutsideOfDomain(const Pslg& pslg, const SegmentMembership& membership) : pslg_(pslg), mem_(membership) {}
  // The input vertices on no triangle of m and the segments no edge of m lies on
  // (both unchanged by refinement: it never reaches outside the domain).
  const OutsideInput& of(const TriMesh& m);

 private:
  const Pslg& pslg_;
  const SegmentMembership& mem_;
  bool ready_ = false;
  OutsideInput items_;
};

}  // namespace lepp::fast
