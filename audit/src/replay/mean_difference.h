// SPDX-License-Identifier: GPL-3.0-or-later
// Private to the conformance replay: the difference between a program's coordinate
// and a choice's that is the mean of two, three or four doubles (a midpoint, a
// triangle's centroid, the quad's vertex centroid), rounded to a double exactly as
// CGAL's to_double rounds the lazy difference, without GMP. Where to_double's
// interval is too wide it evaluates the
// difference exactly (a rational, then MPFR's tightest interval, then its centre):
// for a program's point within a few ulps of its choice, every step of a
// conforming trace, and a third of a long replay's time. Here the exact value is
// an expansion of doubles (error-free sums), its tightest interval checked exactly;
// anything this cannot decide (subnormal or huge values) is left to CGAL.
#pragma once
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <utility>

#include "double_predicates.h"   // reference/src: sum_error (Knuth's TwoSum)
#include "exact_constructions.h"  // even_of
#include "triangulation.h"        // reference/src: the exact engine's CGAL types

namespace lepp::audit::replay_detail {

using namespace lepp::reference::detail;

// A point that is the mean of n doubles per coordinate (n = 2, 3 or 4; 0: not known to be).
struct MeanOf {
  std::array<double, 4> x{}, y{};
  int n = 0;
};

namespace mean_detail {

// An expansion: up to 8 non-overlapping doubles, smallest first; their exact sum.
struct Expansion {
  std::array<double, 8> c{};
  std::size_t size = 0;
  bool ok = true;  // false after an overflow: the sum is not known

  void add(double b) {  // Shewchuk's Grow-Expansion
    if (size == c.size()) {
      ok = false;
      return;
    }
    double q = b;
    for (std::size_t i = 0; i < size; ++i) {
      const double s = q + c[i];
      c[i] = sum_error(q, c[i], s);
      q = s;
    }
    c[size++] = q;
    for (std::size_t i = 0; i < size; ++i) ok = ok && std::isfinite(c[i]);
  }
  // The sign of the exact sum: its largest non-zero component's.
  int sign() const {
    for (std::size_t i = size; i-- > 0;)
      if (c[i] != 0) return c[i] > 0 ? 1 : -1;
    return 0;
  }
  double approx() const {
    double s = 0;
    for (std::size_t i = 0; i < size; ++i) s += c[i];
    return s;
  }
};

constexpr double kSmall = 0x1p-900, kLarge = 0x1p+1000;
inline bool in_range(double t) { return t == 0 || (std::abs(t) > kSmall && std::abs(t) < kLarge); }
inline bool known_count(int n) { return n == 2 || n == 3 || n == 4; }

// sign * n * x added to e exactly (n = 2, 3 or 4, |x| within range): a power of two
// scales exactly; 3 x is its rounded product and that product's error (fma: exact,
// the product neither overflows nor underflows within range).
inline void add_multiple(Expansion& e, int n, double x, double sign) {
  const double p = n * x;
  e.add(sign * p);
  if (n == 3) e.add(sign * std::fma(3.0, x, -p));
}

// The value e / n of an exact sum e (n = 2, 3 or 4) placed among the doubles: h and its
// neighbour `other` on the value's side, the value strictly between them, and `at` the
// side (1: above h, -1: below; 0: the value is h and `other` is h). None when it cannot
// be decided here (values out of range).
struct Placed {
  double h, other;
  int at;
};
inline std::optional<Placed> place(const Expansion& e, int n) {
  if (!e.ok) return std::nullopt;
  if (e.sign() == 0) return Placed{0, 0, 0};
  const double h = e.approx() / n;  // a guess, checked exactly below
  if (!in_range(h) || h == 0) return std::nullopt;
  auto compare = [&](double x) {  // the sign of e - n x, exactly
    Expansion r = e;
    add_multiple(r, n, x, -1);
    return r.ok ? r.sign() : 2;
  };
  const int at = compare(h);
  if (at == 2) return std::nullopt;
  if (at == 0) return Placed{h, h, 0};
  const double other = std::nextafter(h, at > 0 ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity());
  if (!in_range(other) || compare(other) != -at) return std::nullopt;  // not strictly between: left to CGAL
  return Placed{h, other, at};
}

inline bool all_in_range(const double* m, int n) {
  for (int i = 0; i < n; ++i)
    if (!in_range(m[i])) return false;
  return true;
}

}  // namespace mean_detail

// The tightest interval of doubles around v - (m_1 + ... + m_n) / n, as CGAL's
// To_interval gives it for a rational (both ends the value when it is a double; else
// the two doubles around it). None when it cannot be made here: n not 2, 3 or 4, a value
// not finite, or one near the subnormal range or the largest doubles.
inline std::optional<std::pair<double, double>> mean_difference_interval(double v, const double* m, int n) {
  using namespace mean_detail;
  if (!known_count(n) || !in_range(v) || !all_in_range(m, n)) return std::nullopt;
  Expansion e;  // n v - sum m, exactly
  add_multiple(e, n, v, 1);
  for (int i = 0; i < n; ++i) e.add(-m[i]);
  const std::optional<Placed> x = place(e, n);
  if (!x) return std::nullopt;
  if (x->at == 0) return std::make_pair(x->h, x->h);
  return x->at > 0 ? std::make_pair(x->h, x->other) : std::make_pair(x->other, x->h);
}

// The double nearest to (m_1 + ... + m_n) / n, ties to even (round_nearest of the
// exact mean); none when it cannot be decided here (as above).
inline std::optional<double> mean_nearest(const double* m, int n) {
  using namespace mean_detail;
  if (!known_count(n) || !all_in_range(m, n)) return std::nullopt;
  Expansion e;
  for (int i = 0; i < n; ++i) e.add(m[i]);
  const std::optional<Placed> x = place(e, n);
  if (!x) return std::nullopt;
  if (x->at == 0) return x->h;
  // Which side of the midpoint of h and other: the sign of 2 e - n (h + other), exactly.
  Expansion twice;
  for (std::size_t i = 0; i < e.size; ++i) twice.add(2 * e.c[i]);
  add_multiple(twice, n, x->h, -1);
  add_multiple(twice, n, x->other, -1);
  if (!twice.ok) return std::nullopt;
  const int side = twice.sign() * x->at;  // 1: nearer other, -1: nearer h, 0: a tie
  if (side < 0) return x->h;
  if (side > 0) return x->other;
  return even_of(x->h, x->other);
}

// CGAL::to_double(FT(v) - q) for the coordinate q of a point that is the mean of the
// doubles m[0..n): the same double, computed as CGAL's to_double computes it (the
// lazy difference's interval when it is a point or narrow enough; else the centre of
// the exact value's tightest interval), the last without GMP where it can.
inline double difference_to_double(double v, const FT& q, const double* m, int n) {
  const FT diff = FT(v) - q;
  // CGAL's own branch, no exact arithmetic: the interval a point, or narrow enough.
  if (n == 0 || CGAL::has_smaller_relative_precision(CGAL::approx(diff), FT::get_relative_precision_of_to_double()))
    return CGAL::to_double(diff);
  if (const auto tight = mean_difference_interval(v, m, n)) return (tight->second + tight->first) * 0.5;
  return CGAL::to_double(diff);
}

}  // namespace lepp::audit::replay_detail
