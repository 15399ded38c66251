// SPDX-License-Identifier: GPL-3.0-or-later
// An open finding of the batch order (docs/FUZZING.md, "The batch order on a subnormal
// fan"), pinned so that a change to the round definition shows here: on a square with
// vertices a few subnormals from a corner, every round has one member, and the run grows
// cubically in the points (fuzz_differential timed out under LEPP_FUZZ_ORDER=batch).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lepp/fast.h"
#include "lepp/io.h"
#include "lepp/reference.h"
#include "lepp/validate.h"

namespace lepp {
namespace {

Pslg fan() {
  std::vector<std::string> warnings;
  return validate(read_poly(std::string(LEPP_SOURCE_DIR) + "/corpus/regressions/precision/batch-subnormal-fan.poly"), warnings);
}

RefineOptions batch() {
  RefineOptions o;
  o.order = QueueOrder::Batch;
  o.min_angle_deg = 10;
  o.max_steiner = 200;  // the first 200 points: a fraction of a second, the pattern already plain
  o.threads = 1;
  return o;
}

// The finding as it stands: about one round per point (196 rounds for 200 points), in both
// engines alike. A definition of rounds that lets the fan's waiting triangles join (or skip
// them cheaply) makes this fail: then the finding is fixed and the test says so.
TEST(BatchOpenFinding, SubnormalFanRoundsOfOneMember_OpenFinding) {
  const Pslg p = fan();
  const RefineResult f = fast::refine(p, batch());
  const RefineResult r = reference::refine(p, batch());
  EXPECT_EQ(f.outcome, Outcome::SteinerBudget);
  EXPECT_EQ(f.steiner_points, 200);
  EXPECT_GE(f.rounds, 190) << "rounds now take several members each: the open finding is fixed";
  EXPECT_EQ(f.rounds, r.rounds);
  EXPECT_EQ(f.mesh.vertices, r.mesh.vertices);
}

// The fifo order on the same input ends, and the corpus sweep certifies its meshes.
TEST(BatchOpenFinding, SubnormalFanFifoEnds) {
  RefineOptions o;
  o.min_angle_deg = 10;
  const RefineResult f = fast::refine(fan(), o);
  EXPECT_EQ(f.outcome, Outcome::Unimprovable);
  EXPECT_EQ(f.steiner_points, 3225);
}

}  // namespace
}  // namespace lepp
