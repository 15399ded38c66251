// SPDX-License-Identifier: GPL-3.0-or-later
// Exact plane geometry for the theorem checks: CORE::Expr numbers (exact
// +, -, *, /, sqrt with exact sign decisions), so that cos 30 = sqrt(3)/2,
// half angles and longest-edge coordinates stay exact. Angles against
// constants that are not algebraic in a handy form (0.79 alpha, 14 degrees)
// go through certified MPFR brackets (AngleBracket), never acos in double.
// Internal to lepp_theorems: CGAL stays out of the public headers.
#pragma once
#include <CGAL/CORE_Expr.h>

#include <string>

#include "lepp/theorems/checks.h"

namespace lepp::theorems::exact {

using FT = CORE::Expr;

struct P {
  FT x, y;
};
inline P pt(const GridPoint& g) { return {FT(static_cast<double>(g.x)), FT(static_cast<double>(g.y))}; }
inline P operator-(const P& a, const P& b) { return {a.x - b.x, a.y - b.y}; }
inline P operator+(const P& a, const P& b) { return {a.x + b.x, a.y + b.y}; }
inline P operator*(const FT& k, const P& a) { return {k * a.x, k * a.y}; }
inline FT dot(const P& u, const P& v) { return u.x * v.x + u.y * v.y; }
inline FT cross(const P& u, const P& v) { return u.x * v.y - u.y * v.x; }
inline FT norm2(const P& u) { return dot(u, u); }
inline FT dist2(const P& a, const P& b) { return norm2(a - b); }
inline P midpoint(const P& a, const P& b) { return FT(0.5) * (a + b); }
// Sign of the turn a -> b -> c: > 0 counter-clockwise.
inline int orient(const P& a, const P& b, const P& c) { return CGAL::sign(cross(b - a, c - a)); }

// cos of the angle at `apex` between rays to p and q: exact.
FT cos_at(const P& apex, const P& p, const P& q);
// Angle comparisons through cosines (cos decreases on [0, pi]).
inline bool angle_ge(const FT& cos_a, const FT& cos_b) { return cos_a <= cos_b; }
// cos(alpha/2), cos(3 alpha/2), cos(2 alpha) from cos(alpha), alpha in [0, pi].
FT cos_half(const FT& c);
FT cos_three_halves(const FT& c);
FT cos_double(const FT& c);

// Exact cosines of the paper's constants.
FT cos_deg30();
FT cos_deg120();
FT cos_alpha_limit();  // alpha_limit = arctan((sqrt 15 - sqrt 3)/(3 + sqrt 5)), about 22.24 degrees

// A certified bracket [lo, hi] (degrees) of an angle given by its exact cosine.
struct AngleBracket {
  double lo = 0, hi = 0;
};
AngleBracket angle_deg(const FT& cos_value);
// Tri-state comparison a >= k*b of bracketed angles: Yes, No, or Tie when the
// brackets overlap within 1e-9 degrees (reported, never silently decided).
enum class Cmp { Yes, No, Tie };
Cmp ge(const AngleBracket& a, double k, const AngleBracket& b);
Cmp ge_const(const AngleBracket& a, double deg);

// A triangle labelled as in the paper's Fig. 3: BC <= CA <= BA, so BA is the
// longest edge, the smallest angle alpha0 is at A; M is the midpoint of BA;
// longest-edge bisection by CM gives t_A = AMC and t_B = BMC; alpha1 = angle
// MCA (at C in t_A) and beta = angle BMC = alpha0 + alpha1.
struct Fig3 {
  P A, B, C, M;
  FT ba2, ca2, bc2;  // squared edge lengths
  FT cos_alpha0, cos_alpha1, cos_beta, cos_gamma;  // gamma: the angle at C (largest)
};
Fig3 fig3(const P& p, const P& q, const P& r);
// Labelled exactly as given (B, A, C), for the negative tests that drop "BA is longest".
Fig3 fig3_as_given(const P& B, const P& A, const P& C);
bool is_obtuse(const Fig3& t);  // gamma > 90
bool is_acute(const Fig3& t);   // gamma < 90
FT min_angle_cos(const P& a, const P& b, const P& c);  // cos of the smallest angle

std::string show(const P& p);

}  // namespace lepp::theorems::exact
