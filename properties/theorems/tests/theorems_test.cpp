// SPDX-License-Identifier: GPL-3.0-or-later
// One RapidCheck property per statement of the paper, run by ctest (label
// `theorems`) with the fixed seed of the certificate (RC_PARAMS set by CMake).
// The bodies live in lepp_theorems so that `lepp theorems` runs the same code.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <iostream>

#include "lepp/theorems/statements.h"

namespace {
void body(const char* id) {
  const auto* s = lepp::theorems::find_statement(id);
  RC_ASSERT(s != nullptr);
  s->property();
}
}  // namespace

#define LEPP_STATEMENT(Suite, Name) \
  RC_GTEST_PROP(Suite, Name, ()) { body(#Suite "." #Name); }

// A statement that fails as written (a documented finding): the same property,
// run with the certificate's seed and case count, must find a counterexample.
// Its narrowed statement is an LEPP_STATEMENT; the shrunk counterexample is
// replayed from corpus/theorems by corpus_test.cpp.
#define LEPP_FINDING(Suite, Name)                                                         \
  TEST(Suite, Name##_OpenFinding) {                                                       \
    const auto* s = lepp::theorems::find_statement(#Suite "." #Name);                     \
    ASSERT_NE(s, nullptr);                                                                \
    ASSERT_FALSE(s->finding.empty());                                                     \
    auto outcome = lepp::theorems::run_statement(*s, lepp::theorems::kDefaultCases, 0,    \
                                                 lepp::theorems::kSeed);                  \
    EXPECT_FALSE(outcome.passed) << "the finding did not reproduce";                      \
    std::cout << "counterexample: " << outcome.counterexample << "\n";                   \
  }

LEPP_STATEMENT(Theorem1, MinAngleAtLeastHalfAlpha0)
LEPP_STATEMENT(Theorem1, FinitelyManySimilarityClasses)
LEPP_STATEMENT(Theorem1, QuasiEquilateralShareGrows)
LEPP_STATEMENT(Theorem2, TerminalTrianglesLargestAngleAtMost120)
LEPP_STATEMENT(Theorem2, EqualityCaseCocircularWithEquilateral)
LEPP_STATEMENT(Proposition3, Alpha1AtLeastHalfAlpha0)
LEPP_STATEMENT(Proposition3, ObtuseAlpha1AtLeastAlpha0)
LEPP_FINDING(Lemma4, BisectionImprovesTBLeavesObtuseTA)
LEPP_STATEMENT(Lemma4, HoldsWhenBCShorterThanCA)
LEPP_STATEMENT(Proposition6, MidpointNearestVertexOfOwnTriangle)
LEPP_FINDING(Proposition6, MidpointNearestVertexInDelaunayMesh)
LEPP_STATEMENT(Proposition6, AcuteWorstRatioIsIsosceles)
LEPP_STATEMENT(Proposition6, ObtuseWorstRatioIs120Triangle)
LEPP_STATEMENT(Lemma7, AcuteAlpha1AtLeast079Alpha0)
LEPP_STATEMENT(Lemma7, AcuteAlpha1AtLeast0866Alpha0BelowAlphaLimit)
LEPP_STATEMENT(Lemma7, Alpha1OverAlpha0TendsToOne)
LEPP_STATEMENT(Lemma7, BetaAtLeast179Alpha0)
LEPP_STATEMENT(Lemma7, ObtuseAlpha1AboveAlpha0)
LEPP_FINDING(Lemma8, AcuteBelowAlphaLimitDistanceAbove13)
LEPP_STATEMENT(Lemma8, AcuteBelowAlphaLimitOwnDistanceAbove129)
LEPP_FINDING(Lemma8, AcuteBelow30DistanceAbove096)
LEPP_STATEMENT(Lemma8, AcuteBelow30OwnDistanceAbove096)
LEPP_STATEMENT(Lemma8, ObtuseBelow14DistanceAboveBC)
LEPP_STATEMENT(Lemma8, ObtuseBelowAlphaLimitDistanceAbove066)
LEPP_STATEMENT(Lemma8, ObtuseBelow30DistanceAtLeastHalf)
LEPP_STATEMENT(Lemma8, ObtuseAbove14BetaAbove28)
LEPP_STATEMENT(Theorem9, BetaChainGrowsGeometrically)
LEPP_STATEMENT(Theorem9, MidpointNotTooCloseToMeshVertices)
LEPP_FINDING(Lemma11, CentroidBoundsInLongestEdgeCoordinates)
LEPP_STATEMENT(Lemma11, CentroidBoundsWithCornerEquality)
LEPP_FINDING(Corollary12, CentroidInsideBetterTriangle)
LEPP_STATEMENT(Corollary12, CentroidInsideBetterTriangleWhenItIsTaller)
LEPP_FINDING(Remark13, CentroidDistanceAtLeast075ShortestEdge)
LEPP_STATEMENT(Remark13, ObtuseCaseDistanceAbove069)
LEPP_STATEMENT(Remark13, NonObtuseCaseDistanceAbove061)
LEPP_FINDING(Theorem14, CentroidNotCollinearExceptRightIsosceles)
LEPP_STATEMENT(Theorem14, CentroidOnTerminalEdgeIffEqualHeights)

// Section 5 and Remark 15: statistics over generated PSLGs (a share, not a per-input assertion).
#define LEPP_STATISTIC(Suite, Name)                                                                          \
  TEST(Suite, Name) {                                                                                        \
    const auto* s = lepp::theorems::find_statement(#Suite "." #Name);                                        \
    ASSERT_NE(s, nullptr);                                                                                   \
    auto outcome = lepp::theorems::run_statement(*s, 0, lepp::theorems::kDefaultInputs, lepp::theorems::kSeed); \
    std::cout << outcome.statistic << "\n";                                                                  \
    EXPECT_TRUE(outcome.passed) << outcome.statistic;                                                        \
  }

LEPP_STATISTIC(Section5, CentroidAddsFewerPoints)
LEPP_STATISTIC(Section5, CentroidHigherAverageSmallestAngle)
LEPP_STATISTIC(Section5, CentroidLongerShortestEdge)
LEPP_STATISTIC(Remark15, CentroidConvergesUpTo30Degrees)
