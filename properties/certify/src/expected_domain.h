// SPDX-License-Identifier: GPL-3.0-or-later
// The domain a correct mesh of a PSLG must cover, computed independently of any
// engine: the CDT of the input (CGAL, exact predicates) flooded from the exterior
// and the hole points without crossing a segment (ALGORITHM.md section 2).
#pragma once
#include <vector>

#include "lepp/certify.h"
#include "lepp/pslg.h"

namespace lepp::certify {

struct ExpectedDomain {
  enum Side : unsigned char { Left = 1, Right = 2 };  // of segment a -> b
  std::vector<char> vertex_in_domain;           // per input vertex: on some domain triangle
  std::vector<unsigned char> segment_sides;     // per segment: Left | Right when that side is domain
  long euler = 0;                               // V - E + F of the domain triangles
  // Per region point: where it lies in the input's CDT, after the holes (the
  // engines' rule, ALGORITHM.md section 2): only Floods sets a region.
  std::vector<RegionPlace> region_places;
};

// pslg must be validated: every segment is then one edge of the CDT.
ExpectedDomain expected_domain(const Pslg& pslg);

}  // namespace lepp::certify
