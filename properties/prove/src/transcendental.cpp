// SPDX-License-Identifier: GPL-3.0-or-later
// The Lemma 7 (I) rows ("Lepp terminal centroid method for quality triangulation",
// Section 3.1, Lemma 7 (I)): alpha1 >= k alpha0 (and beta >= 1.79 alpha0) compare
// angles, so they are not polynomial statements; they are decided by the interval
// branch-and-bound on the triangle B = (0, 0), A = (1, 0), C = (x1, y1).
//
// The claims are about one acute terminal triangle: a proof for every triangle with
// BA longest covers every pair, and a counterexample triangle is terminal in the pair
// with D its mirror image in AB (cocircular, so Delaunay), which is the configuration
// the row's check function is given. The hypotheses put C in the box [0, 1/2] x [0, 1]
// ((1 - x1)^2 <= CA^2 <= 1 gives x1 >= 0, y1^2 <= 1).
//
// The one equality case is the degenerate corner C -> B (alpha0 -> 0, alpha1 -> 0,
// alpha1/alpha0 -> 1), where no interval is ever certain. A box there is closed by Z3
// on an algebraic sufficient condition: alpha1 >= sin alpha1 = sin(alpha0) / (2 CM)
// (the law of sines in M C A, AM = 1/2), sin alpha0 >= alpha0 (1 - alpha0^2 / 6) and
// alpha0 <= u = tan alpha0 = y1 / (1 - x1), so 2 k CM <= 1 - u^2 / 6 gives
// alpha1 >= k alpha0 on the box.
#include <gmpxx.h>

#include "lepp/theorems/lemma7_checks.h"
#include "obligation.h"
#include "solve.h"

namespace lepp::prove {
namespace {
using bnb::Interval;
using bnb::Point;
using namespace lepp::theorems;

struct Spec {
  long k_num, k_den;     // alpha1 >= k alpha0 (beta >= k alpha0 when `beta`)
  bool beta = false;
  const char* bound;     // the hypothesis on alpha0: "alpha0 <= 30", "alpha0 <= alpha_limit", "alpha0 <= 5"
  Lemma7Part part;       // the row's check function, check_lemma7_I_at(.., part, k)
  const char* meaning;   // how the constant k reads (the tight-constant table)
  const char* known;     // the configuration where alpha1/alpha0 (beta/alpha0) is least
};

Spec spec_of(const std::string& statement) {
  if (statement == "Lemma7.AcuteAlpha1AtLeast079Alpha0")
    return {79, 100, false, "alpha0 <= 30", Lemma7Part::a, "alpha1 >= k alpha0 (acute, alpha0 <= 30)",
            "the isosceles triangle BA = CA at alpha0 = 30 (alpha1/alpha0 = 0.793133)"};
  if (statement == "Lemma7.AcuteAlpha1AtLeast0866Alpha0BelowAlphaLimit")
    return {866, 1000, false, "alpha0 <= alpha_limit", Lemma7Part::b,
            "alpha1 >= k alpha0 (acute, alpha0 <= alpha_limit)",
            "the isosceles triangle BA = CA at alpha0 = alpha_limit (alpha1/alpha0 = 0.872599)"};
  if (statement == "Lemma7.Alpha1OverAlpha0TendsToOne")
    return {99, 100, false, "alpha0 <= 5", Lemma7Part::c, "alpha1 >= k alpha0 (acute, alpha0 <= 5)",
            "the isosceles triangle BA = CA at alpha0 = 5 (alpha1/alpha0 = 0.992456)"};
  return {179, 100, true, "alpha0 <= 30", Lemma7Part::d, "beta >= k alpha0 (acute, alpha0 <= 30)",
          "the isosceles triangle BA = CA at alpha0 = 30 (beta/alpha0 = 1.793133)"};
}

// Fig. 3's angles of B A C, C = (x, y) with y > 0, x <= 1/2.
Interval alpha0(const Interval& x, const Interval& y) { return bnb::angle(y, Interval(1) - x); }
Interval alpha1(const Interval& x, const Interval& y) {  // angle MCA: cross y/2, dot (1/2 - x)(1 - x) + y^2
  Interval half = Interval::rational(1, 2);
  return bnb::angle(y * half, (half - x) * (Interval(1) - x) + sqr(y));
}
Interval beta(const Interval& x, const Interval& y) {  // angle BMC: cross y/2, dot (1/2 - x)/2
  Interval half = Interval::rational(1, 2);
  return bnb::angle(y * half, (half - x) * half);
}

z3::expr exact(z3::context& c, double d) { return c.real_val(mpq_class(d).get_str().c_str()); }

// Z3: on the box, the hypotheses kept (algebraic ones) imply 2 k CM <= 1 - u^2 / 6.
bool sine_bound_closes(const bnb::Box& b, long k_num, long k_den, const std::string& dropped) {
  z3::context c;
  z3::solver s = z3::tactic(c, kTactic).mk_solver();
  z3::params prm(c);
  prm.set("timeout", 10000u);
  s.set(prm);
  z3::expr x = c.real_const("x1"), y = c.real_const("y1"), w = c.real_const("cm"), u = c.real_const("u");
  s.add(x >= exact(c, b[0].first) && x <= exact(c, b[0].second) && y >= exact(c, b[1].first) &&
        y <= exact(c, b[1].second));
  auto keep = [&](const char* name, const z3::expr& e) {
    if (dropped != name) s.add(e);
  };
  keep("C above AB (frame)", y > 0);
  keep("BC <= CA", x <= c.real_val(1, 2));
  keep("BA longest", (1 - x) * (1 - x) + y * y <= 1);
  keep("acute", x * x - x + y * y > 0);
  // Unsat: every point of the box meeting the hypotheses kept has alpha0 in (0, pi/2)
  // (y > 0, x < 1: the argument needs it) and meets the closing condition.
  z3::expr misses = w >= 0 && w * w == (c.real_val(1, 2) - x) * (c.real_val(1, 2) - x) + y * y &&
                    u * (1 - x) == y && 2 * c.real_val(k_num) * w > c.real_val(k_den) * (1 - u * u / 6);
  s.add(!(y > 0 && x < 1) || misses);
  return s.check() == z3::unsat;
}

bnb::Problem problem(const Spec& sp, const std::string& dropped) {
  bnb::Problem p;
  p.vars = {{"x1", 0, dropped == "BC <= CA" ? 1.0 : 0.5}, {"y1", 0, 1}};
  auto add = [&](const char* name, bnb::Fn g, bool strict) {
    if (dropped != name) p.hyps.push_back({name, std::move(g), strict});
  };
  add("C above AB (frame)", [](const Point& v) { return v[1]; }, true);
  add("BC <= CA", [](const Point& v) { return Interval::rational(1, 2) - v[0]; }, false);
  add("BA longest", [](const Point& v) { return Interval(1) - sqr(Interval(1) - v[0]) - sqr(v[1]); }, false);
  add("acute", [](const Point& v) { return sqr(v[0]) - v[0] + sqr(v[1]); }, true);
  std::string bound = sp.bound;
  if (bound == "alpha0 <= 30")  // cos alpha0 >= sqrt(3)/2: (1 - x)^2 >= 3 y^2
    add(sp.bound, [](const Point& v) { return sqr(Interval(1) - v[0]) - Interval(3) * sqr(v[1]); }, false);
  else if (bound == "alpha0 <= alpha_limit")  // cos^2 alpha0 >= (7 + 3 sqrt 5)/16
    add(sp.bound,
        [](const Point& v) {
          Interval ca2 = sqr(Interval(1) - v[0]) + sqr(v[1]);
          return Interval(16) * sqr(Interval(1) - v[0]) - (Interval(7) + Interval(3) * bnb::sqrt(Interval(5))) * ca2;
        },
        false);
  else  // alpha0 <= 5 degrees
    add(sp.bound, [](const Point& v) { return Interval::pi() / Interval(36) - alpha0(v[0], v[1]); }, false);
  const Interval k = Interval::rational(sp.k_num, sp.k_den);
  const bool use_beta = sp.beta;
  p.claim = [k, use_beta](const Point& v) {
    return (use_beta ? beta(v[0], v[1]) : alpha1(v[0], v[1])) - k * alpha0(v[0], v[1]);
  };
  // beta = alpha0 + alpha1 (the exterior angle at M of M A C): beta >= 1.79 alpha0 is alpha1 >= 0.79 alpha0.
  long k_num = sp.beta ? sp.k_num - sp.k_den : sp.k_num, k_den = sp.k_den;
  p.close = [k_num, k_den, dropped](const bnb::Box& b) { return sine_bound_closes(b, k_num, k_den, dropped); };
  return p;
}

// Lemma 7 (I)(c)'s right triangles: alpha1 = alpha0 exactly (M is the circumcentre, so
// M C A is isosceles): cos alpha1 = cos alpha0, i.e. (1/2 - x)(1 - x) + y^2 = (1 - x) CM.
std::string right_triangles(double time_limit_s) {
  z3::context c;
  z3::solver s = z3::tactic(c, kTactic).mk_solver();
  z3::params prm(c);
  prm.set("timeout", static_cast<unsigned>(time_limit_s * 1000));
  s.set(prm);
  z3::expr x = c.real_const("x1"), y = c.real_const("y1"), w = c.real_const("cm");
  z3::expr half = c.real_val(1, 2);
  s.add(y > 0 && x <= half && (1 - x) * (1 - x) + y * y <= 1 && x * x - x + y * y == 0);
  s.add(w >= 0 && w * w == (half - x) * (half - x) + y * y);
  s.add((half - x) * (1 - x) + y * y != (1 - x) * w);
  switch (s.check()) {
    case z3::unsat: return "";
    case z3::sat: return "its right-triangle part is refuted by Z3 (alpha1 != alpha0)";
    default: return "its right-triangle part is not decided by Z3: " + s.reason_unknown();
  }
}

}  // namespace

bnb::Problem lemma7_problem(const std::string& statement, const std::string& dropped, long k_num, long k_den) {
  Spec sp = spec_of(statement);
  if (k_den != 0) sp.k_num = k_num, sp.k_den = k_den;
  return problem(sp, dropped);
}

Verdict lemma7_check_at(const std::string& statement, const Config& c, double k) {
  // The triangle B A C with D its mirror image in AB: a Delaunay terminal pair.
  Config m = c;
  m.v = {c.v[0], c.v[1], c.v[0], -c.v[1]};
  return check_lemma7_I_at(m.quad(), spec_of(statement).part, k);
}

Row lemma7_transcendental(const std::string& statement) {
  Spec sp = spec_of(statement);
  Row r;
  r.statement = statement;
  r.shape = Shape::Triangle;
  r.boxes = [sp](const std::string& dropped) { return problem(sp, dropped); };
  if (statement == "Lemma7.Alpha1OverAlpha0TendsToOne") r.side = right_triangles;
  const double k = static_cast<double>(sp.k_num) / static_cast<double>(sp.k_den);
  r.check = [statement, k](const Config& c, bool) { return lemma7_check_at(statement, c, k); };
  r.constant = std::to_string(sp.k_num) + "/" + std::to_string(sp.k_den);
  r.constant_meaning = sp.meaning;
  r.known_extreme = sp.known;
  r.essential = sp.bound;
  r.note = std::string("C -> B closed by Z3 (alpha1 >= sin alpha1 = sin alpha0/(2 CM), sin t >= t - t^3/6)") +
           (sp.beta ? "; beta = alpha0 + alpha1" : "") +
           (r.side ? "; right triangles: alpha1 = alpha0 by Z3" : "");
  return r;
}

}  // namespace lepp::prove
