// SPDX-License-Identifier: GPL-3.0-or-later
// A rigorous interval branch-and-bound (MPFI: outward-rounded interval arithmetic)
// for the statements whose constants involve angles, where the obligation is not a
// polynomial one: for every point of a box of variables meeting the hypotheses
// g_i(x) >= 0 (or > 0), the claim f(x) >= 0 (or > 0). A box is discarded when some
// hypothesis is certainly violated on it, proved when the claim certainly holds on it,
// and a grid point near its middle, evaluated as an exact point, is a counterexample
// when it certainly meets every hypothesis and certainly misses the claim. Boxes that
// reach the minimum width undecided (near an equality or degenerate case) are handed to
// the problem's closer (an algebraic argument, e.g. a Z3 call); those it cannot close
// are left, and a statement with boxes left is not decided. Internal to lepp_prove.
#pragma once
#include <mpfi.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace lepp::prove::bnb {

// An MPFI interval (128-bit endpoints) with value semantics.
class Interval {
 public:
  Interval();
  Interval(double lo, double hi);  // exact endpoints
  explicit Interval(long v) : Interval(static_cast<double>(v), static_cast<double>(v)) {}
  static Interval rational(long num, long den);  // the interval enclosing num/den
  static Interval pi();
  Interval(const Interval& o);
  Interval& operator=(const Interval& o);
  ~Interval();
  mpfi_srcptr get() const { return v_; }
  mpfi_ptr get() { return v_; }
  double lo() const;  // rounded down / up to double: still enclosing
  double hi() const;
  bool nan() const { return mpfi_nan_p(v_) != 0; }
  // Certain signs of every point of the interval (false when NaN).
  bool certainly_ge0() const;  // lo >= 0
  bool certainly_gt0() const;  // lo > 0
  bool certainly_lt0() const;  // hi < 0
  bool certainly_le0() const;  // hi <= 0

 private:
  mpfi_t v_;
};

Interval operator+(const Interval& a, const Interval& b);
Interval operator-(const Interval& a, const Interval& b);
Interval operator*(const Interval& a, const Interval& b);
Interval operator/(const Interval& a, const Interval& b);
Interval operator-(const Interval& a);
Interval sqr(const Interval& a);
Interval sqrt(const Interval& a);
Interval sin(const Interval& a);
Interval atan(const Interval& a);
Interval acos(const Interval& a);
// The angle in [0, pi] whose sine and cosine are proportional to (s, c), s >= 0: atan2(s, c),
// rigorous whatever the sign of c ([0, pi] when neither s nor c is away from 0).
Interval angle(const Interval& s, const Interval& c);

using Point = std::vector<Interval>;
using Fn = std::function<Interval(const Point&)>;
using Box = std::vector<std::pair<double, double>>;

struct Var {
  std::string name;
  double lo = 0, hi = 0;  // every point meeting the hypotheses has lo <= x <= hi
};
struct Hypothesis {
  std::string name;
  Fn g;                 // g >= 0 (g > 0 when strict)
  bool strict = false;
};

struct Problem {
  std::vector<Var> vars;
  std::vector<Hypothesis> hyps;
  Fn claim;             // f >= 0 (f > 0 when strict)
  bool claim_strict = false;
  // A box is not split below this width, relative to the variable's range.
  double min_width = 1.0 / (1 << 16);
  // Counterexamples are points of the grid (1/grid) Z^n, exact doubles for grid = 2^k.
  std::int64_t grid = std::int64_t(1) << 24;
  // Closes a box of minimum width that the intervals do not decide (true: the claim is
  // proved on the box by another argument); none: such boxes are left.
  std::function<bool(const Box&)> close;
  std::size_t max_left = 64;  // stop once this many boxes are left (not decided anyway)
};

enum class Result { Proved, Refuted, NotDecided };
struct Outcome {
  Result result = Result::NotDecided;
  std::vector<double> point;  // Refuted: the counterexample, multiples of 1/grid
  std::size_t boxes = 0;      // boxes examined
  std::size_t closed = 0;     // boxes closed by Problem::close
  std::vector<Box> left;      // boxes of minimum width neither decided nor closed
  bool timed_out = false;
  double seconds = 0;
  std::string why;            // NotDecided: "N boxes left near x in [..], y in [..]" or the time limit
};

Outcome run(const Problem& p, double time_limit_s);
// "x1 in [0.12, 0.13], y1 in [0, 0.001]": the hull of `boxes`.
std::string describe(const Problem& p, const std::vector<Box>& boxes);

}  // namespace lepp::prove::bnb
