// SPDX-License-Identifier: GPL-3.0-or-later
// The angle threshold theta as exact arithmetic sees it.
#pragma once

namespace lepp {

// A certified bracket lo <= sin^2(theta) <= hi of adjacent doubles, from
// correctly rounded (MPFR) arithmetic. For integer theta other than 0, 45 and
// 90 no triangle with double coordinates has an angle of exactly theta (tan
// theta is irrational), so the bracket decides every case but those within one
// ulp of sin^2(theta).
struct Sin2Bracket {
  double lo = 0, hi = 0;
};
Sin2Bracket sin2_bracket(double theta_deg);

// The engines' rule (ALGORITHM.md, "Bad triangle"): an angle alpha <= 90 degrees
// is "below theta" iff sin^2(alpha) < sin2_bracket(theta).hi, compared exactly.
// Rounding up means an engine never calls a triangle good that is not.
inline double engine_sin2_threshold(double theta_deg) { return sin2_bracket(theta_deg).hi; }

}  // namespace lepp
