// SPDX-License-Identifier: GPL-3.0-or-later
// RapidCheck generators of the inputs the paper's statements talk about:
// integer-grid triangles, pairs of Delaunay terminal triangles, point sets for
// Delaunay meshes, and Theorem 2's equality configurations. Small integer
// coordinates shrink to readable counterexamples and keep every predicate exact.
#pragma once
#include <rapidcheck.h>

#include <ostream>
#include <vector>

#include "lepp/theorems/checks.h"

// How RapidCheck prints the generated inputs in a counterexample (found by ADL).
namespace lepp::theorems {
inline void showValue(const GridPoint& p, std::ostream& os) { os << "(" << p.x << ", " << p.y << ")"; }
inline void showValue(const GridTriangle& t, std::ostream& os) { os << show(t); }
inline void showValue(const TerminalQuad& q, std::ostream& os) { os << show(q); }
inline void showValue(const Theorem2EqualityInput& in, std::ostream& os) {
  os << "A (" << in.A.x << ", " << in.A.y << ") B (" << in.B.x << ", " << in.B.y << ") s " << in.s_num << "/" << in.s_den
     << " D offset (" << in.dx << ", " << in.dy << ")/" << in.d_den;
}
}  // namespace lepp::theorems

namespace lepp::theorems::gen {

// A non-degenerate triangle with coordinates in [-range, range]; 1 in 4 is isosceles.
rc::Gen<GridTriangle> triangle(int range = 40);

// A pair ABC, ABD satisfying is_delaunay_terminal_pair. AB = n (p, q) for a random
// integer direction (p, q); C and D are drawn on the lattice spanned by (p, q)
// and its normal, then moved by up to 2 grid steps, so AB has any direction and
// the pair is rarely symmetric, except that 1 in 8 pairs is a mirror kite
// (D the reflection of C), where ties and collinear centroids live.
rc::Gen<TerminalQuad> terminal_quad();

// Lemma 11's corner cases: an obtuse ABC (B = (0, 0), A = (L, 0)) with D exactly at U or
// W, where CC(ABC) meets the lens (|AD| = |AB| or |BD| = |AB|, D cocircular), scaled to integers.
rc::Gen<TerminalQuad> lemma11_corner_quad();

// Points for a Delaunay mesh: 4 to 40 points in [0, 300]^2.
rc::Gen<std::vector<GridPoint>> mesh_points();

// Theorem 2's equality case: C on the 120-degree arc, D at the equilateral apex
// (1 in 8) or moved off it by a small rational offset.
rc::Gen<Theorem2EqualityInput> theorem2_equality();

}  // namespace lepp::theorems::gen
