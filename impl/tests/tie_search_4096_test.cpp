// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 39's run at 4096 Lepp states in both engines (a few seconds in Release, a
// minute or more under the sanitizers: its own executable, labelled slow-under-asan;
// the bound's other tests, tie_search_bound_test.cpp, run under them).
#include <gtest/gtest.h>

#include <cstdio>

#include <fmt/format.h>

#include "lepp/certify.h"
#include "lepp/fast.h"
#include "lepp/reference.h"
#include "result_diff.h"
#include "tie_search_support.h"

namespace lepp {
namespace {

using impl_test::difference;
using namespace tie_search_test;

// Issue 39: the two corpus runs that did not certify at the default bound (the corpus
// sweep, docs/PRECISION.md) certify strictly when both engines and the certifier
// search 4096 Lepp states: tie-finding-subnormal-midpoint.poly by the centroid method at
// 10 and 15 degrees; fast == reference. At the default the same runs leave a claim the
// certifier calls undecided at bound 1024 (TieSearchBound.UnboundedCertifierRejectsTheDefaultMeshWithAWitness).
TEST(TieSearchBound, SubnormalMidpointInputCertifiesAt4096StatesInBothEngines) {
  const Pslg p = load("tie-finding-subnormal-midpoint.poly");
  for (int theta : {10, 15}) {
    SCOPED_TRACE(fmt::format("theta {}", theta));
    const RefineOptions o = options(theta, Method::Centroid, 4096);
    const RefineResult fast_run = fast::refine(p, o), reference_run = reference::refine(p, o);
    EXPECT_EQ(difference(fast_run, reference_run), "");
    const certify::Report rep = certificate(p, fast_run, theta, Method::Centroid, 4096);
    EXPECT_TRUE(rep.certified()) << certify::format_report(rep);
    EXPECT_EQ(count(rep, certify::PrecisionOutcome::Exempt), rep.precision_claims.size());
    std::printf("[ outcome  ] theta %d at 4096 states: %s, %lld Steiner points, %zu claims of double precision, all exempt\n",
                theta, to_string(fast_run.outcome), static_cast<long long>(fast_run.steiner_points), rep.precision_claims.size());
  }
}

}  // namespace
}  // namespace lepp
