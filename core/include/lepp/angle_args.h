// SPDX-License-Identifier: GPL-3.0-or-later
// An angle of the statistics (lepp/stats.h) as the two arguments it gives atan2, and
// the order of two such angles decided without atan2: a triangle's smallest angle then
// costs one atan2, not three, and is the same double (issue 31).
#pragma once
#include <array>

#include "lepp/pslg.h"

namespace lepp {

// The angle at o between o->p and o->q: the cross and dot products of the two
// directions, each direction scaled by a power of two so that its larger component
// is in [1, 2) (no overflow near 1e300, no underflow near 1e-300; issue 19).
struct AngleArgs {
  double cross = 0, dot = 0;
};
AngleArgs angle_args(const Point& o, const Point& p, const Point& q);

// The three angles of triangle abc, at a, b and c: angle_args(a, b, c),
// angle_args(b, c, a), angle_args(c, a, b), from three scaled directions instead of
// six (a reversed direction is the negated one; where that would change the sign of
// a zero, |atan2| is the same).
std::array<AngleArgs, 3> triangle_angle_args(const Point& a, const Point& b, const Point& c);

// triangle_angle_args(a, b, c)[k] from the two sides at corner k only, when the
// three sides have positive, finite lengths whose squares neither overflow nor
// underflow (the caller checks; then triangle_angle_args takes the same path).
AngleArgs corner_angle_args(const Point& a, const Point& b, const Point& c, int k);

// atan2(cross, dot) in degrees, in (-180, 180]: signed_angle_deg's value.
double signed_degrees(const AngleArgs& a);

// True when the angle of a, |signed_degrees(a)|, is certainly smaller than that of b:
// the exact angles of the two argument pairs differ by more than 2^-40 radians (read
// from the sine of their difference, a cross product of the pairs), far more than
// atan2's rounding (a few ulps), so the computed degrees keep the order. False when
// the two are closer (a tie included) or anything is not finite: the caller then
// computes both.
bool clearly_smaller(const AngleArgs& a, const AngleArgs& b);

}  // namespace lepp
