// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind exact.h: exact plane geometry for the theorem checks.
#include "exact.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "lepp/mpfr_thread_cache.h"

namespace lepp::theorems::exact {

FT cos_at(const P& apex, const P& p, const P& q) {
  P u = p - apex, v = q - apex;
  return dot(u, v) / CGAL::sqrt(norm2(u) * norm2(v));
}

FT cos_half(const FT& c) { return CGAL::sqrt((FT(1) + c) / FT(2)); }
FT cos_three_halves(const FT& c) {
  FT h = cos_half(c);
  return FT(4) * h * h * h - FT(3) * h;
}
FT cos_double(const FT& c) { return FT(2) * c * c - FT(1); }

FT cos_deg30() { return CGAL::sqrt(FT(3)) / FT(2); }
FT cos_deg120() { return FT(-0.5); }
FT cos_alpha_limit() {
  FT t = (CGAL::sqrt(FT(15)) - CGAL::sqrt(FT(3))) / (FT(3) + CGAL::sqrt(FT(5)));
  return FT(1) / CGAL::sqrt(FT(1) + t * t);
}

AngleBracket angle_deg(const FT& cos_value) {
  // The exact cosine lies in [clo, chi]; acos is decreasing, so the angle lies in
  // [acos(chi), acos(clo)], each evaluated with directed rounding, then stepped
  // one double outwards.
  std::pair<double, double> iv = CGAL::to_interval(cos_value);
  double clo = std::max(-1.0, iv.first), chi = std::min(1.0, iv.second);
  lepp::free_mpfr_cache_at_thread_exit();
  mpfr_t x, pi;
  mpfr_inits2(128, x, pi, static_cast<mpfr_ptr>(nullptr));
  AngleBracket b;
  mpfr_set_d(x, chi, MPFR_RNDN);
  mpfr_acos(x, x, MPFR_RNDD);
  mpfr_mul_ui(x, x, 180, MPFR_RNDD);
  mpfr_const_pi(pi, MPFR_RNDU);
  mpfr_div(x, x, pi, MPFR_RNDD);
  b.lo = std::nextafter(mpfr_get_d(x, MPFR_RNDD), -1.0);
  mpfr_set_d(x, clo, MPFR_RNDN);
  mpfr_acos(x, x, MPFR_RNDU);
  mpfr_mul_ui(x, x, 180, MPFR_RNDU);
  mpfr_const_pi(pi, MPFR_RNDD);
  mpfr_div(x, x, pi, MPFR_RNDU);
  b.hi = std::nextafter(mpfr_get_d(x, MPFR_RNDU), 1000.0);
  mpfr_clears(x, pi, static_cast<mpfr_ptr>(nullptr));
  return b;
}

Cmp ge(const AngleBracket& a, double k, const AngleBracket& b) {
  const double margin = 1e-9;
  if (a.lo - k * b.hi > margin) return Cmp::Yes;
  if (a.hi - k * b.lo < -margin) return Cmp::No;
  return Cmp::Tie;
}
Cmp ge_const(const AngleBracket& a, double deg) { return ge(a, 1.0, AngleBracket{deg, deg}); }

namespace {
Fig3 make(const P& B, const P& A, const P& C) {
  Fig3 t;
  t.A = A;
  t.B = B;
  t.C = C;
  t.M = midpoint(A, B);
  t.ba2 = dist2(B, A);
  t.ca2 = dist2(C, A);
  t.bc2 = dist2(B, C);
  t.cos_alpha0 = cos_at(A, B, C);
  t.cos_alpha1 = cos_at(C, t.M, A);
  t.cos_beta = cos_at(t.M, B, C);
  t.cos_gamma = cos_at(C, A, B);
  return t;
}
}  // namespace

Fig3 fig3(const P& p, const P& q, const P& r) {
  // C is opposite the longest edge, A opposite the shortest; ties by position.
  P v[3] = {p, q, r};
  FT opp[3] = {dist2(q, r), dist2(p, r), dist2(p, q)};
  int c = 0, a = 0;
  for (int i = 1; i < 3; ++i) {
    if (opp[i] > opp[c]) c = i;
    if (opp[i] < opp[a]) a = i;
  }
  if (a == c) a = (c + 1) % 3;  // all equal
  int b = 3 - a - c;
  return make(v[b], v[a], v[c]);
}

Fig3 fig3_as_given(const P& B, const P& A, const P& C) { return make(B, A, C); }

// Any of the three angles (for a Fig. 3 labelling the largest is at C; a negative
// test may label a triangle whose obtuse angle is elsewhere).
namespace {
int smallest_cos_sign(const Fig3& t) {
  int a = CGAL::sign(dot(t.B - t.A, t.C - t.A)), b = CGAL::sign(dot(t.A - t.B, t.C - t.B));
  int c = CGAL::sign(dot(t.A - t.C, t.B - t.C));
  return std::min(a, std::min(b, c));
}
}  // namespace
bool is_obtuse(const Fig3& t) { return smallest_cos_sign(t) < 0; }
bool is_acute(const Fig3& t) { return smallest_cos_sign(t) > 0; }

FT min_angle_cos(const P& a, const P& b, const P& c) {
  FT ca = cos_at(a, b, c), cb = cos_at(b, a, c), cc = cos_at(c, a, b);
  return std::max(ca, std::max(cb, cc));
}

std::string show(const P& p) {
  std::ostringstream s;
  s << "(" << CGAL::to_double(p.x) << ", " << CGAL::to_double(p.y) << ")";
  return s.str();
}

}  // namespace lepp::theorems::exact

namespace lepp::theorems {
// For hypotheses "theta <= alpha_limit" on user-given thetas; angle decisions use cos_alpha_limit().
double alpha_limit_deg() { return std::atan((std::sqrt(15.0) - std::sqrt(3.0)) / (3 + std::sqrt(5.0))) * 180 / M_PI; }
}  // namespace lepp::theorems
