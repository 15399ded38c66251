// SPDX-License-Identifier: GPL-3.0-or-later
// The bound of the search of every resolution of exact length ties at the precision
// limit (ALGORITHM.md section 8b; docs/CERTIFIER.md section 5c; issue 39): an option
// of both engines (RefineOptions::tie_search_states) and of the certifier
// (certify::Options::tie_search_states), 1024 Lepp states by default, 0 no bound; the
// certificate's three outcomes for a triangle listed at double precision.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

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

TEST(TieSearchBound, DefaultIs1024LeppStatesInTheEnginesAndTheCertifier) {
  EXPECT_EQ(kTieSearchStates, 1024u);
  EXPECT_EQ(RefineOptions{}.tie_search_states, 1024u);
  EXPECT_EQ(certify::Options{}.tie_search_states, 1024u);
}

// The bound reaches each engine: on tie-finding.poly at 20 degrees the default's
// search inserts through another tie resolution; with a bound of one state it
// cannot follow any other Lepp, so the run differs. Both engines agree at each bound.
// With no bound (0) the run is the default's: every search there ends within 1024 states.
TEST(TieSearchBound, ReachesEachEngine) {
  const Pslg p = load("tie-finding.poly");
  const RefineOptions wide = options(20, Method::Centroid, kTieSearchStates), narrow = options(20, Method::Centroid, 1);
  const RefineResult fast_wide = fast::refine(p, wide), fast_narrow = fast::refine(p, narrow);
  const RefineResult reference_wide = reference::refine(p, wide), reference_narrow = reference::refine(p, narrow);
  EXPECT_EQ(difference(fast_wide, reference_wide), "");
  EXPECT_EQ(difference(fast_narrow, reference_narrow), "");
  EXPECT_GT(fast_wide.tie_resolutions, 0);
  EXPECT_NE(difference(fast_wide, fast_narrow), "") << "the fast engine ignores tie_search_states";
  EXPECT_NE(difference(reference_wide, reference_narrow), "") << "the reference ignores tie_search_states";
  EXPECT_LT(fast_narrow.tie_resolutions, fast_wide.tie_resolutions);
  EXPECT_LT(reference_narrow.tie_resolutions, reference_wide.tie_resolutions);
  // 0 is no bound: here every search ends within the default, so the run is the default's.
  const RefineOptions unbounded = options(20, Method::Centroid, 0);
  EXPECT_EQ(difference(fast::refine(p, unbounded), fast_wide), "") << "the fast engine takes 0 for a bound of 0 states";
  EXPECT_EQ(difference(reference::refine(p, unbounded), reference_wide), "") << "the reference takes 0 for a bound of 0 states";
}

// The three outcomes on one claim: lepp's mesh of tie-finding.poly at 20 degrees leaves
// triangles at double precision that the certifier proves exempt at the default bound;
// at a bound of one state the same claims are undecided at bound 1, and at a time limit
// already passed undecided at the time limit: named, never accepted.
TEST(TieSearchBound, ClaimsAreExemptOrUndecidedAtTheBoundNamed) {
  const Pslg p = load("tie-finding.poly");
  const RefineResult r = fast::refine(p, options(20, Method::Centroid, kTieSearchStates));
  const certify::Report proved = certificate(p, r, 20, Method::Centroid, kTieSearchStates);
  ASSERT_TRUE(proved.certified()) << certify::format_report(proved);
  ASSERT_FALSE(proved.precision_claims.empty()) << "the input no longer leaves a triangle at double precision";
  EXPECT_EQ(count(proved, certify::PrecisionOutcome::Exempt), proved.precision_claims.size());
  EXPECT_EQ(proved.tie_search_states, kTieSearchStates);
  // Proved within the bound: the engine's own search saw every state of these too.
  for (const UnimprovableTriangle& u : r.unimprovable) EXPECT_FALSE(u.search_cut);

  const certify::Report bounded = certificate(p, r, 20, Method::Centroid, 1);
  EXPECT_FALSE(bounded.certified());
  ASSERT_GT(count(bounded, certify::PrecisionOutcome::Undecided), 0u) << certify::format_report(bounded);
  EXPECT_EQ(bounded.precision_undecided, count(bounded, certify::PrecisionOutcome::Undecided));
  EXPECT_EQ(count(bounded, certify::PrecisionOutcome::Rejected), 0u);
  bool named = false;
  for (const certify::Violation& v : bounded.violations)
    named |= v.reason == certify::Reason::UnimprovableRuleFails &&
             v.message.find("stopped undecided at bound 1 Lepp states") != std::string::npos;
  EXPECT_TRUE(named) << certify::format_report(bounded);
  EXPECT_NE(certify::format_report(bounded).find("undecided at bound 1 Lepp states"), std::string::npos);

  certify::Options late;
  late.min_angle_deg = 20;
  late.unimprovable = r.unimprovable;
  late.tie_search_states = 0;
  late.time_limit_seconds = 1e-9;  // passed before the first search starts
  const certify::Report timed = certify::certify(p, r.mesh, late);
  ASSERT_EQ(count(timed, certify::PrecisionOutcome::Undecided), timed.precision_claims.size());
  EXPECT_EQ(timed.precision_claims.front().undecided, certify::PrecisionUndecided::TimeLimit);
  EXPECT_NE(certify::format_report(timed).find("stopped undecided at the time limit"), std::string::npos);
}

// A recorded known violation (docs/THEOREMS.md, "The precision stop and exact length
// ties"): at the default bound both engines leave a triangle of the same input
// (centroid, 10 degrees) whose claim the certifier at 1024 states names undecided at
// bound 1024, and the certifier with no bound rejects with a witness: a point another
// tie resolution reaches that can be inserted, printed with its exact coordinates and
// the choice that reaches it.
TEST(TieSearchBound, UnboundedCertifierRejectsTheDefaultMeshWithAWitness) {
  const Pslg p = load("tie-finding-subnormal-midpoint.poly");
  const RefineResult r = fast::refine(p, options(10, Method::Centroid, kTieSearchStates));
  const certify::Report bounded = certificate(p, r, 10, Method::Centroid, kTieSearchStates);
  ASSERT_GT(bounded.precision_undecided, 0u) << certify::format_report(bounded);
  EXPECT_EQ(count(bounded, certify::PrecisionOutcome::Rejected), 0u) << certify::format_report(bounded);
  EXPECT_NE(certify::format_report(bounded).find("stopped undecided at bound 1024 Lepp states"), std::string::npos);

  const certify::Report unbounded = certificate(p, r, 10, Method::Centroid, 0);
  EXPECT_FALSE(unbounded.certified());
  // The rejected claims are on triangles both engines left with their search cut at
  // the bound (UnimprovableTriangle::search_cut), and only there may a rejection come.
  const RefineResult rr = reference::refine(p, options(10, Method::Centroid, kTieSearchStates));
  for (const certify::PrecisionClaim& c : unbounded.precision_claims) {
    if (c.outcome != certify::PrecisionOutcome::Rejected) continue;
    Tri t = r.mesh.triangles[static_cast<std::size_t>(c.triangle)];
    std::sort(t.begin(), t.end());
    for (const RefineResult* engine : {&r, &rr}) {
      bool listed_cut = false;
      for (const UnimprovableTriangle& u : engine->unimprovable) {
        Tri v = u.triangle;
        std::sort(v.begin(), v.end());
        listed_cut |= v == t && u.search_cut;
      }
      EXPECT_TRUE(listed_cut) << (engine == &r ? "fast" : "reference") << ": triangle " << c.triangle
                              << " is rejected but not marked as cut by the bound";
    }
  }
  EXPECT_EQ(unbounded.precision_undecided, 0u);
  ASSERT_GT(count(unbounded, certify::PrecisionOutcome::Rejected), 0u) << certify::format_report(unbounded);
  for (const certify::PrecisionClaim& c : unbounded.precision_claims) {
    if (c.outcome != certify::PrecisionOutcome::Rejected) continue;
    const certify::PrecisionWitness& w = c.witness;
    // The choice starts at the claimed triangle, one edge taken as longest per triangle of the Lepp.
    ASSERT_FALSE(w.lepp.empty());
    EXPECT_EQ(w.lepp.front(), c.triangle);
    EXPECT_EQ(w.lepp.size(), w.longest.size());
    EXPECT_GT(c.states, kTieSearchStates) << "decided within the default bound: the bound would not matter here";
    for (const Point& v : r.mesh.vertices) EXPECT_FALSE(v == w.point) << "the witness is a mesh vertex";
    // Printed: the point exactly (hexadecimal), the branch and the Lepp.
    const std::string text = certify::format_report(unbounded);
    EXPECT_NE(text.find(fmt::format("= ({:a}, {:a})", w.point.x, w.point.y)), std::string::npos) << text;
    EXPECT_NE(text.find(fmt::format("branch {}", to_string(w.rule))), std::string::npos) << text;
    EXPECT_NE(text.find(fmt::format("Lepp triangle {} (longest {}-{})", c.triangle, w.longest[0][0], w.longest[0][1])),
              std::string::npos)
        << text;
    // A Lepp of thousands of triangles along the strip: both ends named, the middle counted (the JSON has all).
    ASSERT_GT(w.lepp.size(), 7u);
    const std::size_t n = w.lepp.size();
    EXPECT_NE(text.find(fmt::format("... {} more triangles ... -> triangle {} (longest {}-{})", n - 6, w.lepp[n - 3],
                                    w.longest[n - 3][0], w.longest[n - 3][1])),
              std::string::npos)
        << text;
    EXPECT_NE(text.find(fmt::format("-> triangle {} (longest {}-{}), terminal pair", w.lepp.back(), w.longest.back()[0],
                                    w.longest.back()[1])),
              std::string::npos)
        << text;
  }
}

}  // namespace
}  // namespace lepp
