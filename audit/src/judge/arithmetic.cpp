// SPDX-License-Identifier: GPL-3.0-or-later
// single-precision, float-input, printed-digits: what the numbers a program wrote say about its arithmetic.
#include "lepp/audit/judge/arithmetic.h"

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <set>
#include <utility>

#include <fmt/format.h>

#include "lepp/audit/replay.h"

namespace lepp::audit {
namespace {

bool is_float(double x) { return std::isfinite(x) && nearest_float(x) == x; }
bool is_float(const Point& p) { return is_float(p.x) && is_float(p.y); }

// x written with d significant digits and read back (printf's rounding, as a stream's).
double with_digits(double x, int d) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", d, x);
  return std::strtod(buf, nullptr);
}

// The most digits a program can write short of a double's 17: a stream at
// setprecision(16) (digits10 + 1) moves every coordinate that needs 17.
constexpr int kMostPrintedDigits = 16;

// The fewest significant digits that read back as x; 17 for any x that needs
// more than 16 (all the rules ask; two conversions for most doubles a program computed).
int digits_of(double x) {
  if (!std::isfinite(x) || x == 0) return 1;
  if (with_digits(x, kMostPrintedDigits) != x) return 17;
  if (with_digits(x, 15) != x) return 16;
  for (int d = 1; d < 15; ++d)
    if (with_digits(x, d) == x) return d;
  return 15;
}
int digits_of(const Point& p) { return std::max(digits_of(p.x), digits_of(p.y)); }

// Half a unit in the d-th significant digit of x: how far writing x with d digits moves it
// (and a millionth more, for the rounding of this bound itself).
double half_digit_unit(double x, int d) {
  if (x == 0 || !std::isfinite(x)) return 0;
  return 0.5 * (1 + 1e-6) * std::pow(10.0, std::floor(std::log10(std::abs(x))) - d + 1);
}

std::string pt(const Point& p) { return fmt::format("({:.17g}, {:.17g})", p.x, p.y); }

// The mesh test for one rounding: every input vertex it moves is at its rounding, none kept.
ArithmeticEvidence moved_by(const Pslg& input, const std::set<std::pair<double, double>>& out, const std::string& name,
                            const std::function<Point(const Point&)>& round) {
  ArithmeticEvidence e;
  std::size_t kept = 0;
  std::string example;
  for (std::size_t i = 0; i < input.vertices.size(); ++i) {
    const Point& v = input.vertices[i];
    const Point r = round(v);
    if (r == v) continue;
    ++e.rounded;
    if (out.count({v.x, v.y})) ++kept;
    else if (out.count({r.x, r.y}) && e.moved++ == 0) example = fmt::format("input vertex {} {} is at {}", i, pt(v), pt(r));
  }
  if (e.moved > 0 && kept == 0) {
    e.name = name;
    e.what = fmt::format("{} of the {} input vertices it moves are in the output at that rounding, none where they are; {}",
                         e.moved, e.rounded, example);
  }
  return e;
}

}  // namespace

ArithmeticEvidence mesh_arithmetic(const Pslg& input, const Mesh& mesh) {
  std::set<std::pair<double, double>> out;
  int digits = 0;
  bool floats = !mesh.vertices.empty();
  for (const Point& v : mesh.vertices) {
    out.insert({v.x, v.y});
    digits = std::max(digits, digits_of(v));
    floats = floats && is_float(v);
  }
  if (digits > 0 && digits <= kMostPrintedDigits) {
    ArithmeticEvidence e = moved_by(input, out, "printed-digits", [&](const Point& p) {
      return Point{with_digits(p.x, digits), with_digits(p.y, digits)};
    });
    if (!e.name.empty()) {
      e.digits = digits;
      e.what = fmt::format("coordinates written with at most {} significant digits (a double needs up to 17): {}", digits, e.what);
      return e;
    }
  }
  // Every coordinate a float: the program holds its points as floats. Only its
  // input vertices at their float rounding: it reads its input as float and
  // computes its own points in double.
  ArithmeticEvidence e = moved_by(input, out, floats ? "single-precision" : "float-input", [](const Point& p) {
    return Point{nearest_float(p.x), nearest_float(p.y)};
  });
  if (!e.name.empty())
    e.what = (floats ? "every output coordinate is a float, and " : "the input vertices are floats, not the points it added: ") + e.what;
  return e;
}

ArithmeticEvidence step_arithmetic(const ConformanceFailure& f) {
  ArithmeticEvidence e;
  if (f.candidates.empty()) return e;
  const ConformanceCandidate& c = f.candidates.front();  // the nearest of the paper's choices
  const Point& p = f.point;
  const int digits = digits_of(p);
  // The program's own double may be off the choice by the point tolerance (the
  // replay would have taken it written in full); writing it with D digits moves
  // it by half a unit of the D-th digit, and reading that back by half an ulp more,
  // which the tolerance covers too.
  auto printed_from = [&](double written, double choice) {
    return std::abs(written - choice) <=
           std::max(half_digit_unit(written, digits), half_digit_unit(choice, digits)) + c.tolerance;
  };
  if (digits <= kMostPrintedDigits && digits_of(c.point) > digits && printed_from(p.x, c.point.x) &&
      printed_from(p.y, c.point.y)) {
    e.name = "printed-digits";
    e.digits = digits;
    e.what = fmt::format("the point {} has {} significant digits and is the paper's choice {} ({}) written with "
                         "{} digits (a double needs up to 17)",
                         pt(p), digits, pt(c.point), to_string(c.rule), digits);
    return e;
  }
  // The replay's point tolerance is so many DBL_EPSILON x the choice's scale: the same in FLT_EPSILON.
  const double float_tolerance = c.tolerance * (FLT_EPSILON / DBL_EPSILON);
  if (is_float(p) && !is_float(c.point) && c.distance <= float_tolerance) {
    e.name = "single-precision";
    e.what = fmt::format("the point {} is a float {:.3g} from the paper's choice {} ({}), within the point "
                         "tolerance in float units ({:.3g}); the choice is no float",
                         pt(p), c.distance, pt(c.point), to_string(c.rule), float_tolerance);
  }
  return e;
}

const char* arithmetic_definition(const std::string& name) {
  if (name == "single-precision")
    return "the program holds coordinates as float: its points (or the input vertices it wrote) sit at a float next to the "
           "exact value, beyond a double's rounding";
  if (name == "float-input")
    return "the program reads its input coordinates as float and computes in double: it meshes the input vertices at their "
           "float rounding, a slightly different input, so its points are not the paper's choices on the input given";
  if (name == "printed-digits")
    return "the program writes coordinates with fewer significant digits than a double needs (a stream's default 6, say): "
           "the points read back are not the ones it computed";
  return "";
}

}  // namespace lepp::audit
