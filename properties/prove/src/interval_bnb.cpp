// SPDX-License-Identifier: GPL-3.0-or-later
// The interval branch-and-bound: MPFI intervals and the box search (interval_bnb.h).
#include "interval_bnb.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace lepp::prove::bnb {
namespace {
constexpr mpfr_prec_t kPrecision = 128;

// One endpoint of v (mpfi_get_left or mpfi_get_right), rounded to double in the
// direction that keeps it enclosing.
double endpoint(mpfi_srcptr v, int (*get)(mpfr_ptr, mpfi_srcptr), mpfr_rnd_t rounding) {
  mpfr_t e;
  mpfr_init2(e, kPrecision);
  get(e, v);
  const double d = mpfr_get_d(e, rounding);
  mpfr_clear(e);
  return d;
}

template <class F>
Interval unary(const Interval& a, F f) {
  Interval r;
  f(r.get(), a.get());
  return r;
}
template <class F>
Interval binary(const Interval& a, const Interval& b, F f) {
  Interval r;
  f(r.get(), a.get(), b.get());
  return r;
}
}  // namespace

Interval::Interval() { mpfi_init2(v_, kPrecision); }
Interval::Interval(double lo, double hi) : Interval() { mpfi_interv_d(v_, lo, hi); }
Interval::Interval(const Interval& o) : Interval() { mpfi_set(v_, o.v_); }
Interval& Interval::operator=(const Interval& o) {
  if (this != &o) mpfi_set(v_, o.v_);
  return *this;
}
Interval::~Interval() { mpfi_clear(v_); }
Interval Interval::rational(long num, long den) {
  Interval r;
  mpfi_set_si(r.v_, num);
  mpfi_div_si(r.v_, r.v_, den);
  return r;
}
Interval Interval::pi() {
  Interval r;
  mpfi_const_pi(r.v_);
  return r;
}
double Interval::lo() const { return endpoint(v_, mpfi_get_left, MPFR_RNDD); }
double Interval::hi() const { return endpoint(v_, mpfi_get_right, MPFR_RNDU); }
// The endpoints compared with 0 exactly (rounding to double keeps the sign).
bool Interval::certainly_ge0() const { return !nan() && lo() >= 0; }
bool Interval::certainly_gt0() const { return !nan() && lo() > 0; }
bool Interval::certainly_lt0() const { return !nan() && hi() < 0; }
bool Interval::certainly_le0() const { return !nan() && hi() <= 0; }

Interval operator+(const Interval& a, const Interval& b) { return binary(a, b, mpfi_add); }
Interval operator-(const Interval& a, const Interval& b) { return binary(a, b, mpfi_sub); }
Interval operator*(const Interval& a, const Interval& b) { return binary(a, b, mpfi_mul); }
Interval operator/(const Interval& a, const Interval& b) { return binary(a, b, mpfi_div); }
Interval operator-(const Interval& a) { return unary(a, mpfi_neg); }
Interval sqr(const Interval& a) { return unary(a, mpfi_sqr); }
Interval sqrt(const Interval& a) { return unary(a, mpfi_sqrt); }
Interval sin(const Interval& a) { return unary(a, mpfi_sin); }
Interval atan(const Interval& a) { return unary(a, mpfi_atan); }
Interval acos(const Interval& a) { return unary(a, mpfi_acos); }

Interval angle(const Interval& s, const Interval& c) {
  if (c.certainly_gt0()) return atan(s / c);                   // in [0, pi/2)
  if (c.certainly_lt0()) return Interval::pi() - atan(s / -c);  // in (pi/2, pi]
  if (s.certainly_gt0()) return Interval::pi() / Interval(2) - atan(c / s);
  return Interval(0, 4);  // contains [0, pi]
}

namespace {

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

Point as_point(const Box& b) {
  Point p;
  for (const auto& [lo, hi] : b) p.emplace_back(lo, hi);
  return p;
}

// Some hypothesis is false at every point of the box.
bool violated(const Problem& p, const Point& x) {
  for (const Hypothesis& h : p.hyps) {
    Interval g = h.g(x);
    if (h.strict ? g.certainly_le0() : g.certainly_lt0()) return true;
  }
  return false;
}
// Every hypothesis is true at every point of the box.
bool met(const Problem& p, const Point& x) {
  for (const Hypothesis& h : p.hyps) {
    Interval g = h.g(x);
    if (!(h.strict ? g.certainly_gt0() : g.certainly_ge0())) return false;
  }
  return true;
}
bool claim_holds(const Problem& p, const Interval& f) { return p.claim_strict ? f.certainly_gt0() : f.certainly_ge0(); }
bool claim_fails(const Problem& p, const Interval& f) { return p.claim_strict ? f.certainly_le0() : f.certainly_lt0(); }

// The grid point nearest the box's middle, if it lies in the box.
bool grid_middle(const Problem& p, const Box& b, std::vector<double>* out) {
  out->clear();
  const double g = static_cast<double>(p.grid);
  for (const auto& [lo, hi] : b) {
    double m = std::round((lo + hi) / 2 * g) / g;
    if (m < lo || m > hi) return false;
    out->push_back(m);
  }
  return true;
}

double relative_width(const Problem& p, const Box& b, std::size_t i) {
  double range = p.vars[i].hi - p.vars[i].lo;
  return range > 0 ? (b[i].second - b[i].first) / range : 0;
}

}  // namespace

Outcome run(const Problem& p, double time_limit_s) {
  auto t0 = std::chrono::steady_clock::now();
  Outcome out;
  Box whole;
  for (const Var& v : p.vars) whole.emplace_back(v.lo, v.hi);
  std::vector<Box> stack{whole};
  std::vector<double> mid;
  while (!stack.empty()) {
    if (since(t0) > time_limit_s) {
      out.timed_out = true;
      break;
    }
    Box b = std::move(stack.back());
    stack.pop_back();
    ++out.boxes;
    Point x = as_point(b);
    if (violated(p, x)) continue;
    if (claim_holds(p, p.claim(x))) continue;
    if (grid_middle(p, b, &mid)) {
      Point m;
      for (double v : mid) m.emplace_back(v, v);
      if (met(p, m) && claim_fails(p, p.claim(m))) {
        out.result = Result::Refuted;
        out.point = mid;
        out.seconds = since(t0);
        return out;
      }
    }
    std::size_t widest = 0;
    for (std::size_t i = 1; i < b.size(); ++i)
      if (relative_width(p, b, i) > relative_width(p, b, widest)) widest = i;
    if (relative_width(p, b, widest) <= p.min_width) {
      if (p.close && p.close(b)) {
        ++out.closed;
        continue;
      }
      out.left.push_back(b);
      if (out.left.size() >= p.max_left) break;
      continue;
    }
    double cut = (b[widest].first + b[widest].second) / 2;
    Box lower = b, upper = b;
    lower[widest].second = cut;
    upper[widest].first = cut;
    stack.push_back(std::move(upper));
    stack.push_back(std::move(lower));
  }
  out.seconds = since(t0);
  if (out.timed_out) {
    out.why = "time limit (" + std::to_string(static_cast<int>(time_limit_s)) + " s) reached with " +
              std::to_string(stack.size() + 1) + " boxes open";
    return out;
  }
  if (!out.left.empty()) {
    out.why =
        std::to_string(out.left.size()) + (stack.empty() ? "" : "+") + " boxes left near " + describe(p, out.left);
    return out;
  }
  out.result = Result::Proved;
  return out;
}

std::string describe(const Problem& p, const std::vector<Box>& boxes) {
  std::string s;
  for (std::size_t i = 0; i < p.vars.size() && !boxes.empty(); ++i) {
    double lo = boxes[0][i].first, hi = boxes[0][i].second;
    for (const Box& b : boxes) lo = std::min(lo, b[i].first), hi = std::max(hi, b[i].second);
    char buf[96];
    std::snprintf(buf, sizeof buf, "%s%s in [%.6g, %.6g]", i ? ", " : "", p.vars[i].name.c_str(), lo, hi);
    s += buf;
  }
  return s;
}

}  // namespace lepp::prove::bnb
