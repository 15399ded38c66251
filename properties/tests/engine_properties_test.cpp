// SPDX-License-Identifier: GPL-3.0-or-later
// The core properties of the engines (issue 3), on generated PSLGs, for the
// reference engine and the fast engine, both methods, checked by the certifier:
//  1. the CDT an engine builds certifies, and Theorem 2 holds on it;
//  2. on PSLGs with input angles >= 60 degrees, refinement converges within the
//     Steiner budget steiner_budget(P) below and certifies with min angle >= theta:
//     the centroid method for theta <= 30, the midpoint method for theta <= 22
//     (the paper's alpha_limit: above it the midpoint method has a loop case, and
//     midpoint_loop_test.cpp holds a shrunk input where it loops at 30 degrees);
//  3. on any PSLG refinement ends (converged, budget, floor or unimprovable) and its
//     output certifies as a CDT (with min angle >= theta when it says converged, and
//     the unimprovable triangles' rule checked when it says unimprovable);
//  4. Theorem 2 (and the whole CDT certificate) holds on every intermediate mesh.
// Deterministic: a fixed seed unless RC_PARAMS sets one (rc_defaults.cpp).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "lepp/certify.h"
#include "lepp/engines/registry.h"
#include "lepp/gen.h"
#include "lepp/validate.h"

namespace lepp {

// RapidCheck prints a shrunk Method by name (found by argument-dependent lookup).
inline void showValue(Method m, std::ostream& os) { os << to_string(m); }

namespace {

// lepp's engines by the registry: refine and build_cdt found by argument-dependent lookup.
using engines::Engine;

const char* name(Engine e) { return engines::to_string(e); }

Pslg validated(const Pslg& p) {
  std::vector<std::string> warnings;
  return validate(p, warnings);
}

// The Steiner budget of property 2, a function of the input alone:
//   steiner_budget(P) = 100 + 10 (V + S) + 8 A / d^2
// with V, S the numbers of input vertices and segments, A the area of the
// bounding box and d the smallest distance between two input vertices. A quality
// mesh grades from edges of length ~d, so A / d^2 bounds the number of triangles
// of that size the box holds; measured maxima are reported by the property
// (RC_TAG of the used fraction) so the constant is visibly not tight-fitted.
std::int64_t steiner_budget(const Pslg& p) {
  double xmin = std::numeric_limits<double>::infinity(), ymin = xmin, xmax = -xmin, ymax = -xmin;
  for (const Point& v : p.vertices) {
    xmin = std::min(xmin, v.x), xmax = std::max(xmax, v.x), ymin = std::min(ymin, v.y), ymax = std::max(ymax, v.y);
  }
  double d2 = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < p.vertices.size(); ++i)
    for (std::size_t j = i + 1; j < p.vertices.size(); ++j) {
      const double dx = p.vertices[i].x - p.vertices[j].x, dy = p.vertices[i].y - p.vertices[j].y;
      d2 = std::min(d2, dx * dx + dy * dy);
    }
  const double area = (xmax - xmin) * (ymax - ymin);
  return 100 + 10 * static_cast<std::int64_t>(p.vertices.size() + p.segments.size()) + static_cast<std::int64_t>(8 * area / d2);
}

std::string used_fraction_tag(std::int64_t used, std::int64_t budget) {
  const double f = static_cast<double>(used) / static_cast<double>(budget);
  return f < 0.01 ? "budget used <1%" : f < 0.1 ? "budget used <10%" : f < 0.5 ? "budget used <50%" : "budget used >=50%";
}

void require_certified(const certify::Report& r, const std::string& what) {
  if (!r.certified()) RC_FAIL(what + "\n" + certify::format_report(r));
}

Method any_method() { return *rc::gen::element(Method::Centroid, Method::Midpoint); }

// --- 1 -----------------------------------------------------------------------
void cdt_certifies(Engine e) {
  const Pslg p = validated(*gen::anyPslg());
  RC_TAG(p.source);
  const Mesh m = build_cdt(e, p);
  const certify::Report r = certify::certify(p, m);
  RC_CLASSIFY(r.stats.terminal_pairs_checked > 0, "has unconstrained terminal pairs");
  RC_CLASSIFY(r.stats.cocircular_edges > 0, "cocircular edges");
  require_certified(r, std::string(name(e)) + " CDT");
}

// --- 2 -----------------------------------------------------------------------
void converges_within_budget(Engine e) {
  const Pslg p = validated(*gen::wellShapedPslg());
  RefineOptions o;
  o.method = any_method();
  o.min_angle_deg = o.method == Method::Centroid ? *rc::gen::element(20.0, 25.0, 28.0, 30.0) : *rc::gen::element(15.0, 20.0, 22.0);
  o.max_steiner = steiner_budget(p);
  RC_TAG(p.source, to_string(o.method), o.min_angle_deg);
  const RefineResult r = refine(e, p, o);
  RC_TAG(used_fraction_tag(r.steiner_points, o.max_steiner));
  if (r.outcome != Outcome::Converged)
    RC_FAIL(std::string(name(e)) + " did not converge: " + to_string(r.outcome) + " after " + std::to_string(r.steiner_points) +
            " Steiner points, budget " + std::to_string(o.max_steiner) + "; " + r.stuck);
  certify::Options c;
  c.min_angle_deg = o.min_angle_deg;
  require_certified(certify::certify(p, r.mesh, c), std::string(name(e)) + " refined mesh");
}

// --- 3 -----------------------------------------------------------------------
void any_input_ends_certified(Engine e) {
  const Pslg p = validated(*gen::anyPslg());
  RefineOptions o;
  o.method = any_method();
  o.min_angle_deg = *rc::gen::inRange(10, 36);
  o.max_steiner = 3000;  // small: the point is that every run ends with a valid mesh
  RC_TAG(p.source, to_string(o.method));
  const RefineResult r = refine(e, p, o);
  RC_TAG(to_string(r.outcome));
  certify::Options c;
  if (r.outcome == Outcome::Converged || r.outcome == Outcome::Unimprovable) {
    c.min_angle_deg = o.min_angle_deg;
    c.unimprovable = r.unimprovable;
  }
  RC_ASSERT(r.outcome != Outcome::Converged || r.unimprovable.empty());
  RC_ASSERT(r.outcome != Outcome::Unimprovable || !r.unimprovable.empty());
  const certify::Report report = certify::certify(p, r.mesh, c);
  require_certified(report, std::string(name(e)) + " output, outcome " + to_string(r.outcome));
  RC_ASSERT(report.unimprovable_accepted.size() == (c.min_angle_deg > 0 ? r.unimprovable.size() : 0u));
}

// --- 4 -----------------------------------------------------------------------
void every_intermediate_mesh_certifies(Engine e) {
  Pslg p = validated(*rc::gen::oneOf(gen::wellShapedPslg(), gen::pointCloudInBox(), gen::boxWithCracks(), gen::polygonWithHole()));
  RC_PRE(p.vertices.size() <= 60);
  RefineOptions o;
  o.method = any_method();
  o.min_angle_deg = *rc::gen::element(25.0, 30.0, 33.0);
  o.max_steiner = 150;
  std::string failure;
  std::int64_t checked = 0;
  o.on_insertion = [&](const Mesh& m) {
    if (!failure.empty()) return;
    ++checked;
    const certify::Report r = certify::certify(p, m);
    if (!r.certified()) failure = "after insertion " + std::to_string(checked) + ":\n" + certify::format_report(r);
  };
  RC_TAG(p.source, to_string(o.method));
  refine(e, p, o);
  RC_CLASSIFY(checked >= 20, "20+ intermediate meshes");
  if (!failure.empty()) RC_FAIL(std::string(name(e)) + " " + failure);
}

RC_GTEST_PROP(ReferenceEngine, CdtCertifiesAndTheorem2Holds, ()) { cdt_certifies(Engine::Reference); }
RC_GTEST_PROP(ReferenceEngine, WellShapedInputConvergesWithinBudgetAndCertifies, ()) { converges_within_budget(Engine::Reference); }
RC_GTEST_PROP(ReferenceEngine, AnyInputEndsWithCertifiedMesh, ()) { any_input_ends_certified(Engine::Reference); }
RC_GTEST_PROP(ReferenceEngine, Theorem2OnEveryIntermediateMesh, ()) { every_intermediate_mesh_certifies(Engine::Reference); }

RC_GTEST_PROP(FastEngine, CdtCertifiesAndTheorem2Holds, ()) {
  cdt_certifies(Engine::Fast);
}
RC_GTEST_PROP(FastEngine, WellShapedInputConvergesWithinBudgetAndCertifies, ()) {
  converges_within_budget(Engine::Fast);
}
RC_GTEST_PROP(FastEngine, AnyInputEndsWithCertifiedMesh, ()) {
  any_input_ends_certified(Engine::Fast);
}
RC_GTEST_PROP(FastEngine, Theorem2OnEveryIntermediateMesh, ()) {
  every_intermediate_mesh_certifies(Engine::Fast);
}

}  // namespace
}  // namespace lepp
