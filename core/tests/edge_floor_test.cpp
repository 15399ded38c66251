// SPDX-License-Identifier: GPL-3.0-or-later
// The default edge floor is 2^-20 x the input's smallest feature: the shortest
// segment, the closest two vertices, or the closest vertex to a segment it does
// not end (ALGORITHM.md, "Termination: guards").
#include <gtest/gtest.h>

#include <cmath>

#include "lepp/refine.h"

namespace lepp {
namespace {

Pslg unit_square() {
  Pslg p;
  p.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}, {3, 0, 0}};
  return p;
}

TEST(DefaultEdgeFloor, ShortestSegment) { EXPECT_EQ(default_edge_floor(unit_square()), std::ldexp(1.0, -20)); }

TEST(DefaultEdgeFloor, ClosestVertices) {
  // corpus/hostile/near-touching.poly: two slit tips 1e-12 apart, segments 0.2 and longer.
  Pslg p = unit_square();
  p.vertices.insert(p.vertices.end(), {{0, 0.4}, {0.5, 0.5}, {0, 0.6}, {0.5, 0.500000000001}});
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}, {3, 6, 0}, {6, 4, 0}, {4, 0, 0}, {4, 5, 0}, {6, 7, 0}};
  EXPECT_EQ(default_edge_floor(p), std::ldexp(p.vertices[7].y - p.vertices[5].y, -20));
}

TEST(DefaultEdgeFloor, VertexNearASegment) {
  // A segment from the centre down to 1e-9 above the bottom side's middle.
  Pslg p = unit_square();
  p.vertices.insert(p.vertices.end(), {{0.5, 0.5}, {0.5, 1e-9}});
  p.segments.push_back({4, 5, 0});
  EXPECT_EQ(default_edge_floor(p), std::ldexp(1e-9, -20));
}

TEST(DefaultEdgeFloor, NoSegmentsNoVertices) { EXPECT_EQ(default_edge_floor(Pslg{}), 0); }

}  // namespace
}  // namespace lepp
