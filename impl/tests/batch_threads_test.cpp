// SPDX-License-Identifier: GPL-3.0-or-later
// The batch order on several threads (docs/ALGORITHM.md section 7, "Threads"):
// the same run, step by step and round by round, for every number of threads.
// The paper's inputs are large enough that the default windows are split among
// the threads (a window of fewer than 512 untouched triangles per thread is looked
// at on one); generated ones use tiny windows. The ThreadSanitizer build of
// scripts/ci.d/ runs these tests too.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <ostream>
#include <string>
#include <vector>

#include "lepp/fast.h"
#include "lepp/input.h"
#include "lepp/io.h"
#include "lepp/validate.h"
#include "random_pslg.h"
#include "result_diff.h"

namespace lepp {
namespace {

Pslg load(const std::string& path) {
  std::vector<std::string> warnings;
  const std::string full = std::string(LEPP_SOURCE_DIR) + "/corpus/" + path;
  const bool points = full.size() > 5 && full.substr(full.size() - 5) == ".node";
  DomainOptions domain;
  domain.convex_hull = points;  // a point set: its convex hull, as lepp refine meshes it
  return validate(points ? read_node(full) : read_poly(full), domain, warnings);
}

RefineOptions batch(double theta, double max_area, Method method, int threads) {
  RefineOptions o;
  o.order = QueueOrder::Batch;
  o.min_angle_deg = theta;
  o.max_area = max_area;
  o.method = method;
  o.threads = threads;
  o.trace = true;
  return o;
}

struct Case {
  const char* input;
  double theta, max_area;
  Method method;
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.input << " at " << c.theta << " degrees, max area " << c.max_area << (c.method == Method::Midpoint ? ", midpoint" : ", centroid");
}

class BatchThreads : public ::testing::TestWithParam<Case> {};

// One thread against 2, 3 and 8: the same mesh, statistics, rounds and trace.
TEST_P(BatchThreads, SameRunForEveryNumberOfThreads) {
  const Case& c = GetParam();
  const Pslg p = load(c.input);
  const RefineResult one = fast::refine(p, batch(c.theta, c.max_area, c.method, 1));
  ASSERT_GT(one.mesh.triangles.size(), 20000u) << "too small for the threads to share a window";
  for (const int threads : {2, 3, 8}) {
    SCOPED_TRACE(threads);
    const RefineResult many = fast::refine(p, batch(c.theta, c.max_area, c.method, threads));
    EXPECT_EQ(impl_test::difference(one, many), "");
    EXPECT_EQ(impl_test::trace_difference(one.trace, many.trace), "");
    EXPECT_EQ(one.rounds, many.rounds);
    EXPECT_EQ(one.lepp_searches, many.lepp_searches);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Paper, BatchThreads,
    ::testing::Values(Case{"paper/square400.poly", 30, 0.15, Method::Centroid},
                      Case{"paper/rect162.poly", 33, 0.00005, Method::Centroid},
                      Case{"paper/circles240.poly", 25, 0.0001, Method::Centroid},
                      Case{"paper/A.poly", 20, 0.000005, Method::Midpoint}),
    [](const ::testing::TestParamInfo<Case>& info) {
      std::string name = info.param.input;
      name = name.substr(name.find('/') + 1);
      name = name.substr(0, name.find('.'));
      return name + (info.param.method == Method::Midpoint ? "_midpoint" : "_centroid");
    });

// 30,000 points in near-duplicate clusters at 20 degrees: rounds with triangles at
// the limit of double precision (a choice that is not plain waits to be a round's
// first member, then settles on the round's mesh), on one thread and on two.
TEST(BatchThreads, PrecisionStopsAreTheSameOnTwoThreads) {
  const Pslg p = load("regressions/precision/neardup30k.node");
  const RefineResult one = fast::refine(p, batch(20, 0, Method::Centroid, 1));
  const RefineResult two = fast::refine(p, batch(20, 0, Method::Centroid, 2));
  EXPECT_GT(one.precision_stops, 0);
  EXPECT_EQ(impl_test::difference(one, two), "");
  EXPECT_EQ(impl_test::trace_difference(one.trace, two.trace), "");
}

// Random PSLGs with windows of 1 to 4 entries per thread, so that small inputs are
// split among the threads in every round: the same run as one thread's.
RC_GTEST_PROP(BatchThreads, TinyWindowsGiveTheSameRunOnGeneratedInputs, ()) {
  const Pslg p = impl_test::to_pslg(*impl_test::gen_raw_pslg(16, 24));
  RC_PRE(!p.vertices.empty());
  const double theta = *rc::gen::inRange(15, 34);
  const Method method = *rc::gen::element(Method::Centroid, Method::Midpoint);
  const double max_area = *rc::gen::inRange(0, 3) == 0 ? 4.0 / *rc::gen::inRange(20, 400) : 0.0;
  RefineOptions many = batch(theta, max_area, method, *rc::gen::inRange(2, 6));
  many.batch_window = *rc::gen::inRange(1, 5);
  many.max_steiner = 20000;
  RefineOptions one = many;
  one.threads = 1;
  const RefineResult a = fast::refine(p, one), b = fast::refine(p, many);
  RC_ASSERT(impl_test::difference(a, b) == "");
  RC_ASSERT(impl_test::trace_difference(a.trace, b.trace) == "");
}

// threads = 0 is the machine's cores: the same run again.
TEST(BatchThreads, ZeroIsTheMachinesCores) {
  const Pslg p = load("paper/square400.poly");
  const RefineResult one = fast::refine(p, batch(30, 0.15, Method::Centroid, 1));
  const RefineResult cores = fast::refine(p, batch(30, 0.15, Method::Centroid, 0));
  EXPECT_EQ(impl_test::difference(one, cores), "");
}

}  // namespace
}  // namespace lepp
