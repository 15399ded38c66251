// SPDX-License-Identifier: GPL-3.0-or-later
// Small hand-made PSLGs for the certifier's tests (integer coordinates: every
// double predicate on them is exact, so the tests can reason about them).
#pragma once
#include <string>
#include <vector>

#include "lepp/input.h"
#include "lepp/io.h"
#include "lepp/pslg.h"
#include "lepp/validate.h"

namespace lepp::test {

inline Pslg validated(const Pslg& p) {
  std::vector<std::string> warnings;
  return validate(p, warnings);
}

// corpus/triangle-formats/crossing.poly of the source tree at `source_dir`,
// validated with its crossing segments split (--split-crossings).
inline Pslg crossing_split(const std::string& source_dir) {
  std::vector<std::string> warnings;
  DomainOptions split;
  split.split_crossings = true;
  return validate(read_poly(source_dir + "/corpus/triangle-formats/crossing.poly"), split, warnings);
}

// The square [0,10]^2 with interior points, an interior segment (the crack, the
// last segment) and, last, an interior vertex on no segment.
inline Pslg square_with_crack() {
  Pslg p;
  p.vertices = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {3, 2}, {6, 7}, {7, 3}, {2, 6}, {8, 8}, {5, 4}, {4, 8}};
  p.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 0, 1}, {4, 5, 0}};
  return validated(p);
}

// The square [0,10]^2 with a square hole [4,6]^2 (hole point at its centre) and a few points.
inline Pslg square_with_hole() {
  Pslg p;
  p.vertices = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {4, 4}, {6, 4}, {6, 6}, {4, 6}, {2, 7}, {8, 2}};
  p.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 0, 1}, {4, 5, 2}, {5, 6, 2}, {6, 7, 2}, {7, 4, 2}};
  p.holes = {{5, 5}};
  return validated(p);
}

}  // namespace lepp::test
