// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind lepp/angle.h: the angle threshold theta as exact arithmetic sees it.
#include "lepp/angle.h"

#include <cmath>

#include "lepp/mpfr_thread_cache.h"

namespace lepp {

Sin2Bracket sin2_bracket(double theta_deg) {
  // sin^2(theta) at 256 bits is within 2^-240 of the truth, far inside one
  // double ulp: rounding it down and up and stepping one more double outwards
  // gives a bracket that holds the exact value.
  free_mpfr_cache_at_thread_exit();
  mpfr_t x, pi;
  mpfr_inits2(256, x, pi, static_cast<mpfr_ptr>(nullptr));
  mpfr_const_pi(pi, MPFR_RNDN);
  mpfr_set_d(x, theta_deg, MPFR_RNDN);
  mpfr_mul(x, x, pi, MPFR_RNDN);
  mpfr_div_ui(x, x, 180, MPFR_RNDN);
  mpfr_sin(x, x, MPFR_RNDN);
  mpfr_sqr(x, x, MPFR_RNDN);
  Sin2Bracket b;
  b.lo = std::nextafter(mpfr_get_d(x, MPFR_RNDD), -1.0);
  b.hi = std::nextafter(mpfr_get_d(x, MPFR_RNDU), 2.0);
  mpfr_clears(x, pi, static_cast<mpfr_ptr>(nullptr));
  return b;
}

}  // namespace lepp
