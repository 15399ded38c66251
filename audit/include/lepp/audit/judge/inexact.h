// SPDX-License-Identifier: GPL-3.0-or-later
// The certifier's findings a double program's rounding explains (docs/CONFORMANCE.md,
// "Declared readings", inexact-threshold and inexact-incircle): a triangle left
// with its smallest angle below theta by no more than double rounding, and an
// edge not locally Delaunay whose quad is cocircular within double rounding of
// the in-circle determinant. Both bounds are decided exactly on the doubles.
#pragma once
#include <cfloat>
#include <cstddef>
#include <string>

#include "lepp/certify.h"
#include "lepp/pslg.h"

namespace lepp::audit {

// |sin^2 alpha - sin^2 theta| below this (sin^2 theta at the far end of its
// certified bracket, lepp/angle.h): alpha is theta up to double rounding. The
// replay's inexact-threshold on the bad side uses the same constant.
constexpr double kThresholdRounding = 16 * DBL_EPSILON;
// |incircle determinant| at most this times its permanent: cocircular up to
// double rounding (Shewchuk's bound for the translated 3x3 form is 5 DBL_EPSILON).
constexpr double kIncircleRounding = 16 * DBL_EPSILON;

constexpr const char* kInexactThreshold = "inexact-threshold";
constexpr const char* kInexactIncircle = "inexact-incircle";

// The smallest angle alpha of triangle abc (the angle opposite a shortest
// edge) has sin^2 alpha > sin2_bracket(theta).lo - kThresholdRounding, exactly.
// For a triangle the certifier found below theta: below only by rounding.
bool angle_within_rounding_below(const Point& a, const Point& b, const Point& c, double theta_deg);

// |det| <= kIncircleRounding * permanent, exactly, for the in-circle
// determinant of d against abc in its translated form (differences to d).
bool incircle_within_rounding(const Point& a, const Point& b, const Point& c, const Point& d);

// A certificate or min-angle row's violations (certify::Report, every one
// listed) that are all of one inexact kind: how many (0: none, or some other
// violation among them). Certificate row: NotLocallyDelaunay edges within
// incircle rounding; min-angle row: triangles below theta within rounding.
// *unlisted (when given) is set when every listed one is within rounding but
// the report counts more than it lists: certify again listing them all.
std::size_t inexact_incircle_edges(const certify::Report& report, bool* unlisted = nullptr);
std::size_t inexact_threshold_triangles(const certify::Report& report, double theta_deg, bool* unlisted = nullptr);

// One sentence each, as in docs/CONFORMANCE.md.
const char* inexact_definition(const std::string& name);

}  // namespace lepp::audit
