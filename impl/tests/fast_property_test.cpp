// SPDX-License-Identifier: GPL-3.0-or-later
// Properties of the fast engine on generated PSLGs in general position.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstdlib>

#include "lepp/certify.h"
#include "lepp/fast.h"
#include "mesh_invariants.h"
#include "random_pslg.h"

namespace lepp {
namespace {

// Deterministic by default: a fixed seed unless RC_PARAMS says otherwise
// (RapidCheck reads it at the first property, after static initialization).
const int fixed_seed = (setenv("RC_PARAMS", "seed=20261122", 0), 0);

RC_GTEST_PROP(FastProperty, RefinedMeshHoldsTheInvariants, ()) {
  const Pslg p = impl_test::to_pslg(*impl_test::gen_raw_pslg());
  RC_PRE(!p.vertices.empty());
  RefineOptions o;
  o.min_angle_deg = *rc::gen::inRange(15, 35);
  o.method = *rc::gen::element(Method::Centroid, Method::Midpoint);
  o.order = *rc::gen::element(QueueOrder::Fifo, QueueOrder::Lifo);
  o.max_steiner = 5000;
  RefineResult r = fast::refine(p, o);
  RC_CLASSIFY(r.outcome == Outcome::Converged, "converged");
  RC_CLASSIFY(r.outcome == Outcome::Unimprovable, "unimprovable");
  RC_CLASSIFY(r.outcome == Outcome::SteinerBudget, "budget");
  impl_test::InvariantOptions q;
  if (r.outcome == Outcome::Converged || r.outcome == Outcome::Unimprovable) q.min_angle_deg = o.min_angle_deg;
  q.unimprovable = r.unimprovable;
  auto problems = impl_test::check_invariants(p, r.mesh, q);
  RC_ASSERT(problems.empty());
  certify::Options c;
  c.min_angle_deg = q.min_angle_deg;
  c.unimprovable = r.unimprovable;
  certify::Report report = certify::certify(p, r.mesh, c);
  if (!report.certified()) RC_FAIL(certify::format_report(report));
}

}  // namespace
}  // namespace lepp
