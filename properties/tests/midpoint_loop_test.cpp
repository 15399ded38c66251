// SPDX-License-Identifier: GPL-3.0-or-later
// A finding, kept as a regression: on a well-shaped input (a box, two interior
// points, every input angle 90 degrees) Lepp-midpoint at 30 degrees does not
// terminate (the paper's loop case above alpha_limit ~ 22 degrees), while
// Lepp-centroid converges. Both engines; the stopped mesh still certifies as a CDT.
#include <gtest/gtest.h>

#include "lepp/certify.h"
#include "lepp/fast.h"
#include "lepp/io.h"
#include "lepp/reference.h"
#include "lepp/validate.h"

namespace lepp {
namespace {

Pslg loop_input() {
  std::vector<std::string> warnings;
  return validate(read_poly(LEPP_SOURCE_DIR "/properties/tests/data/midpoint_loop_30.poly"), warnings);
}

template <class Refine>
void check_engine(Refine refine) {
  const Pslg p = loop_input();
  RefineOptions o;
  o.min_angle_deg = 30;
  o.max_steiner = 5000;  // far above the centroid's 26 points and any budget of the properties
  o.method = Method::Centroid;
  const RefineResult centroid = refine(p, o);
  EXPECT_EQ(centroid.outcome, Outcome::Converged);
  certify::Options c;
  c.min_angle_deg = 30;
  const auto rc = certify::certify(p, centroid.mesh, c);
  EXPECT_TRUE(rc.certified()) << certify::format_report(rc);

  o.method = Method::Midpoint;
  const RefineResult midpoint = refine(p, o);
  EXPECT_EQ(midpoint.outcome, Outcome::SteinerBudget) << "Lepp-midpoint converged here: the loop is gone; update this record";
  const auto rm = certify::certify(p, midpoint.mesh);  // stopped: still a valid CDT
  EXPECT_TRUE(rm.certified()) << certify::format_report(rm);
  o.min_angle_deg = 22;
  EXPECT_EQ(refine(p, o).outcome, Outcome::Converged);
}

TEST(MidpointLoopFinding, ReferenceEngine) { check_engine([](const Pslg& p, const RefineOptions& o) { return reference::refine(p, o); }); }
TEST(MidpointLoopFinding, FastEngine) {
  check_engine([](const Pslg& p, const RefineOptions& o) { return fast::refine(p, o); });
}

}  // namespace
}  // namespace lepp
