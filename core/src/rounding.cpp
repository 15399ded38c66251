// SPDX-License-Identifier: GPL-3.0-or-later
// The doubles around an exact mean, and the precision floor (lepp/rounding.h).
#include "lepp/rounding.h"

#include <gmp.h>

#include <limits>

namespace lepp {

DoublesAround doubles_around_mean(const double* xs, int n) {
  mpq_t sum, term;
  mpq_inits(sum, term, nullptr);
  for (int i = 0; i < n; ++i) {
    mpq_set_d(term, xs[i]);
    mpq_add(sum, sum, term);
  }
  mpq_set_si(term, n, 1);
  mpq_div(sum, sum, term);
  DoublesAround out;
  // mpq_get_d truncates toward zero; the other neighbour is one step away from zero.
  const double d = mpq_get_d(sum);
  mpq_set_d(term, d);
  const int sign = mpq_cmp(sum, term);
  if (sign == 0) {
    out.value[0] = d, out.count = 1;
  } else {
    const double e = std::nextafter(d, sign > 0 ? HUGE_VAL : -HUGE_VAL);
    out.value[0] = std::min(d, e), out.value[1] = std::max(d, e), out.count = 2;
  }
  mpq_clears(sum, term, nullptr);
  return out;
}

namespace detail {

bool below_precision_floor_exact(const Point& a, const Point& b) {
  const double m = std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(b.x), std::fabs(b.y)});
  const double tiny = std::numeric_limits<double>::denorm_min();
  const double ulp = m > 0 ? std::max(std::ldexp(1.0, std::ilogb(m) - 52), tiny) : tiny;
  const double dx = std::fabs(a.x - b.x), dy = std::fabs(a.y - b.y);
  if (!(dx < 4 * ulp && dy < 4 * ulp)) return false;
  // In doubles, by this one function both engines and the certifier call, so they
  // stop alike; in units of ulp (exact: ulp is a power of two and dx, dy are
  // multiples of the smallest one), so that subnormal differences do not square to zero.
  const double ux = dx / ulp, uy = dy / ulp;
  return ux * ux + uy * uy < 16;
}

}  // namespace detail
}  // namespace lepp
