// SPDX-License-Identifier: GPL-3.0-or-later
// The eight symmetries of the lattice (quarter turns, optionally after the
// mirror x -> -x), on PSLGs and points. Exact on doubles: they only swap and
// negate coordinates, so a mesher run on the transformed input and its points
// mapped back make a trace of the same algorithm on the original input, with
// every geometric decision the same except the ones a tie rule breaks by
// coordinates (CGAL's CDT breaks cocircular ties by the points' lexicographic
// order, which a symmetry changes): a mesher with another tie rule, for free.
#pragma once
#include <ostream>

#include <rapidcheck.h>

#include "lepp/pslg.h"

namespace lepp::gen {

struct LatticeSymmetry {
  int quarter_turns = 0;  // counter-clockwise, 0..3
  bool mirrored = false;  // x -> -x first

  Point apply(Point p) const {
    if (mirrored) p.x = -p.x;
    for (int k = 0; k < quarter_turns; ++k) p = {-p.y, p.x};
    return p;
  }
  Point undo(Point p) const {
    for (int k = 0; k < quarter_turns; ++k) p = {p.y, -p.x};
    if (mirrored) p.x = -p.x;
    return p;
  }
  Pslg apply(Pslg p) const {
    for (Point& v : p.vertices) v = apply(v);
    for (Point& h : p.holes) h = apply(h);
    for (Region& r : p.regions) r.at = apply(r.at);
    return p;
  }
};

/// Any of the eight lattice symmetries (shrinks toward the identity).
inline rc::Gen<LatticeSymmetry> latticeSymmetry() {
  return rc::gen::apply([](int k, bool m) { return LatticeSymmetry{k, m}; }, rc::gen::inRange(0, 4),
                        rc::gen::arbitrary<bool>());
}

inline void showValue(const LatticeSymmetry& s, std::ostream& os) {
  os << s.quarter_turns << " quarter turn(s)" << (s.mirrored ? " after x -> -x" : "");
}

}  // namespace lepp::gen
