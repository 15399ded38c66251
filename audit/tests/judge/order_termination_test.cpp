// SPDX-License-Identifier: GPL-3.0-or-later
// The audit's termination-by-order report (lepp/audit/judge/order_termination.h) on
// the right-angle corner where lepp's lifo loops and fifo converges
// (corpus/regressions/fuzz_refine/open/README.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "lepp/audit/judge/order_termination.h"
#include "lepp/validate.h"

namespace lepp::audit {
namespace {

Pslg corner() {
  Pslg p;
  p.vertices = {{0, 0.1}, {1.6, 0.30000000000000004}, {1.6, 1.6}, {0, 1.6}, {0.1, 0.6000000000000001}};
  p.segments = {{0, 1, 0}, {2, 3, 0}, {3, 0, 0}, {1, 2, 0}};
  std::vector<std::string> warnings;
  return validate(p, warnings);
}

bool has(const std::vector<std::string>& v, const std::string& x) { return std::find(v.begin(), v.end(), x) != v.end(); }

TEST(OrderTermination, AnEngineThatLoopsWhereFifoEndsIsComparedWithEveryOrder) {
  // An engine that did not end at 33 degrees (lepp's lifo does not): fifo ends, lifo does not.
  auto d = compare_termination(corner(), "corner", Method::Centroid, 33, false, 10, 4);
  ASSERT_TRUE(d.has_value());
  EXPECT_TRUE(d->fifo_converged);
  EXPECT_TRUE(has(d->converging, "fifo"));
  EXPECT_FALSE(has(d->converging, "lifo"));
  EXPECT_EQ(d->random_tried, 4);
  const std::string text = format_order_terminations({*d}, 20);
  EXPECT_NE(text.find("corner at theta 33"), std::string::npos) << text;
  EXPECT_EQ(to_json({*d})[0]["lepp_fifo_converged"], true);
}

// Only a run that converged or did not end is compared; one that ended badly (the
// unreadable output of a program writing inf coordinates) is not "does not end".
TEST(OrderTermination, ComparedOnlyForAStatusThatSaysHowTheRunEnded) {
  EXPECT_TRUE(termination_comparable(RunStatus::Ok));
  EXPECT_TRUE(termination_comparable(RunStatus::TimedOut));
  EXPECT_TRUE(termination_comparable(RunStatus::Stopped));
  EXPECT_FALSE(termination_comparable(RunStatus::UnreadableOutput));
  EXPECT_FALSE(termination_comparable(RunStatus::Crashed));
  EXPECT_FALSE(termination_comparable(RunStatus::ExitCode));
}

TEST(OrderTermination, NothingToSayWhenFifoAgrees) {
  EXPECT_FALSE(compare_termination(corner(), "corner", Method::Centroid, 33, true, 10).has_value());
  EXPECT_EQ(format_order_terminations({}, 20), "");
}

}  // namespace
}  // namespace lepp::audit
