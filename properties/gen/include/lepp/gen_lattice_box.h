// SPDX-License-Identifier: GPL-3.0-or-later
// A fixed degenerate input, not a generator: the lattice points of a rectangle's
// boundary (and of every `every`-th row inside), where every unit square is a
// cell of four cocircular points (the conformance replay's tie tests and bench).
#pragma once
#include <cstddef>

#include "lepp/pslg.h"

namespace lepp::gen {

/// The boundary of [0, w] x [0, h] with a vertex at every lattice point on it,
/// as one closed ring of segments (marker 1), plus the interior lattice points of
/// rows every, 2 every, ... below h (none when every is 0). Not validated.
inline Pslg lattice_box(int w, int h, int every = 0) {
  Pslg p;
  for (int x = 0; x < w; ++x) p.vertices.push_back({double(x), 0});
  for (int y = 0; y < h; ++y) p.vertices.push_back({double(w), double(y)});
  for (int x = w; x > 0; --x) p.vertices.push_back({double(x), double(h)});
  for (int y = h; y > 0; --y) p.vertices.push_back({0, double(y)});
  const std::size_t ring = p.vertices.size();
  for (std::size_t i = 0; i < ring; ++i) p.segments.push_back({int(i), int((i + 1) % ring), 1});
  if (every > 0)
    for (int y = every; y < h; y += every)
      for (int x = 1; x < w; ++x) p.vertices.push_back({double(x), double(y)});
  return p;
}

}  // namespace lepp::gen
