// SPDX-License-Identifier: GPL-3.0-or-later
// The default edge floor is 2^-20 x the input's smallest feature: the shortest
// segment, the closest two vertices, or the closest vertex to a segment it does
// not end (ALGORITHM.md, "Termination: guards").
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

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

// The precision floor (ALGORITHM.md section 8b): closer than 4 ulps of the larger coordinate.
double ulps_from(double x, int k) {
  for (; k > 0; --k) x = std::nextafter(x, HUGE_VAL);
  return x;
}

TEST(PrecisionFloor, FourUlpsAtEveryScale) {
  for (double x : {1.0, 0.5, 1e12, 1e-160, 1e-310, 0.0}) {
    const Point a{x, x};
    for (int k = 1; k <= 6; ++k) {
      const Point along{ulps_from(x, k), x}, diagonal{ulps_from(x, k), ulps_from(x, k)};
      // x = 0: the ulp is the smallest subnormal, so both points are k ulps of that from the origin.
      EXPECT_EQ(below_precision_floor(a, along), k < 4) << "x = " << x << ", " << k << " ulps in x";
      // k ulps in both coordinates: sqrt(2) k ulps apart, below 4 only for k <= 2.
      EXPECT_EQ(below_precision_floor(a, diagonal), k <= 2) << "x = " << x << ", " << k << " ulps in x and y";
    }
  }
}

TEST(PrecisionFloor, SubnormalDifferencesDoNotSquareToZero) {
  // Found by the precision campaign (issue 20): near the origin the squared distance of two points a
  // few subnormals apart is 0 in doubles, so the floor never held and refinement went on to edges of
  // one subnormal, 110000 points. Ten ulps apart is not below the floor, at any scale.
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_TRUE(below_precision_floor({0, 0}, {tiny, 2 * tiny}));
  EXPECT_FALSE(below_precision_floor({0, 0}, {10 * tiny, 0}));
  EXPECT_FALSE(below_precision_floor({1e-160, 0}, {ulps_from(1e-160, 10), 0}));
}

}  // namespace
}  // namespace lepp
