// SPDX-License-Identifier: GPL-3.0-or-later
// The batch order's looks (docs/ALGORITHM.md section 7, "batch", step 0): a round ends
// once it has looked at kBatchFreeLooks entries plus kBatchLooksPerMember per member,
// the rest of its queue waiting as it is. Before that rule, a square with vertices a few
// subnormals from a corner made every round look at every waiting triangle and flood
// its cavity (a fan of about N flat triangles): cubic in the points (fuzz_differential
// timed out under LEPP_FUZZ_ORDER=batch; 1000 points took 178 s, docs/FUZZING.md).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lepp/fast.h"
#include "lepp/io.h"
#include "lepp/reference.h"
#include "lepp/validate.h"

namespace lepp {
namespace {

Pslg load(const std::string& path) {
  std::vector<std::string> warnings;
  return validate(read_poly(std::string(LEPP_SOURCE_DIR) + "/corpus/" + path), warnings);
}

Pslg fan() { return load("regressions/precision/batch-subnormal-fan.poly"); }

RefineOptions batch(double theta, std::int64_t max_steiner = -1) {
  RefineOptions o;
  o.order = QueueOrder::Batch;
  o.min_angle_deg = theta;
  o.max_steiner = max_steiner;
  o.threads = 1;
  return o;
}

// What the rule promises of any run: a round's looks are at most kBatchFreeLooks plus
// kBatchLooksPerMember per insertion of that round, so the run's looks are at most that
// per round and per point.
std::int64_t most_looks(const RefineResult& r) {
  return static_cast<std::int64_t>(kBatchLooksPerMember) * r.steiner_points +
         static_cast<std::int64_t>(kBatchFreeLooks) * r.rounds;
}

// The fan still has one member a round (every cavity holds the same fan), but each round
// looks at a few waiting triangles, not all of them: the looks grow with the points
// (about N * N / 2 of them before the rule, half a million for these 1000 points).
TEST(BatchLooks, TheSubnormalFansRoundsLookAtAFewEntriesEach) {
  const Pslg p = fan();
  const RefineResult f = fast::refine(p, batch(10, 1000));
  const RefineResult r = reference::refine(p, batch(10, 1000));
  EXPECT_EQ(f.outcome, Outcome::SteinerBudget);
  EXPECT_EQ(f.steiner_points, 1000);
  EXPECT_GE(f.rounds, 900) << "one member a round, as the fan's cavities all overlap";
  EXPECT_LE(f.looks, most_looks(f));
  EXPECT_LE(f.looks, 11 * f.steiner_points);
  EXPECT_EQ(f.looks, r.looks);
  EXPECT_EQ(f.rounds, r.rounds);
  EXPECT_EQ(f.mesh.vertices, r.mesh.vertices);
  EXPECT_EQ(f.mesh.triangles, r.mesh.triangles);
}

// The whole fan ends in the batch order too (6128 points; fifo makes 3225).
TEST(BatchLooks, TheSubnormalFanEndsInTheBatchOrder) {
  const RefineResult f = fast::refine(fan(), batch(10));
  EXPECT_EQ(f.outcome, Outcome::Unimprovable);
  EXPECT_EQ(f.steiner_points, 6128);
  EXPECT_LE(f.looks, most_looks(f));
}

// The fifo order on the same input ends as well.
TEST(BatchLooks, TheSubnormalFanEndsInTheFifoOrder) {
  RefineOptions o;
  o.min_angle_deg = 10;
  const RefineResult f = fast::refine(fan(), o);
  EXPECT_EQ(f.outcome, Outcome::Unimprovable);
  EXPECT_EQ(f.steiner_points, 3225);
}

// Rounds that end on their looks, on the paper's problem with a size bound (216 rounds
// where looking at the whole queue took 81): both engines alike, within the bound.
TEST(BatchLooks, BothEnginesEndTheSameRoundsOnTheirLooks) {
  RefineOptions o = batch(30);
  o.max_area = 0.5;
  const Pslg p = load("paper/square400.poly");
  const RefineResult f = fast::refine(p, o), r = reference::refine(p, o);
  EXPECT_EQ(f.outcome, Outcome::Converged);
  EXPECT_LE(f.looks, most_looks(f));
  EXPECT_EQ(f.looks, r.looks);
  EXPECT_EQ(f.rounds, r.rounds);
  EXPECT_EQ(f.mesh.vertices, r.mesh.vertices);
}

// The fast engine moves the rest of a round's queue as it is, triangles no longer in
// the mesh included (the reference drops them): a round is counted from its first
// triangle still in the mesh, so a queue of gone triangles is no round (this input made
// 212 rounds against the reference's 211 when every round was counted). Its members
// also keep triangles beside their slivers (section 6), the case where the rest is read
// for the marks, so that each triangle is queued once.
TEST(BatchLooks, AQueueMovedAsItIsMakesTheReferencesRounds) {
  const Pslg p = load("regressions/precision/apex-ulps-chain-walk.poly");
  const RefineResult f = fast::refine(p, batch(30)), r = reference::refine(p, batch(30));
  EXPECT_EQ(f.rounds, r.rounds);
  EXPECT_EQ(f.looks, r.looks);
  EXPECT_EQ(f.mesh.vertices, r.mesh.vertices);
  EXPECT_EQ(f.mesh.triangles, r.mesh.triangles);
}

}  // namespace
}  // namespace lepp
