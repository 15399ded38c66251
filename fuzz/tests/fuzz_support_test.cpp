// SPDX-License-Identifier: GPL-3.0-or-later
// The fuzz targets' own checkers must be able to fail: each test feeds one a
// broken or loop-like input and expects it to say so.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <fstream>
#include <iterator>

#include "support/certify_result.h"
#include "support/cgal_cdt.h"
#include "support/finding.h"
#include "support/fuzz_input.h"
#include "support/known_loops.h"
#include "support/loop_guard.h"
#include "support/same_result.h"

using namespace lepp::fuzz;

namespace {
FuzzInput square_with_hole() {
  FuzzInput in;
  in.grid = 12;
  in.theta_tenths = 281;
  in.method = 1;
  in.order = 1;
  in.scale = 4;
  in.vertices = {{0, 0}, {12, 0}, {12, 12}, {0, 12}, {4, 4}, {8, 4}, {8, 8}, {4, 8}};
  in.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
  in.holes = {{12, 12}};
  return in;
}
}  // namespace

TEST(FuzzInput, EncodeThenDecodeGivesTheSameInput) {
  const FuzzInput in = square_with_hole();
  const std::vector<std::uint8_t> bytes = encode(in);
  const FuzzInput back = decode(bytes.data(), bytes.size());
  EXPECT_EQ(describe(back), describe(in));
}

TEST(FuzzInput, MutationsStayDecodable) {
  std::mt19937 rng(7);
  FuzzInput in = square_with_hole();
  for (int i = 0; i < 2000; ++i) {
    mutate(in, rng);
    const std::vector<std::uint8_t> bytes = encode(in);
    ASSERT_EQ(describe(decode(bytes.data(), bytes.size())), describe(in)) << "after mutation " << i;
  }
}

TEST(FuzzInput, PrecisionCampaignPutsEveryInputInTheFamily) {
  ::setenv("LEPP_FUZZ_PRECISION", "1", 1);
  FuzzInput in = square_with_hole();
  ASSERT_FALSE(in_precision_family(in));
  apply_environment(in);
  ::unsetenv("LEPP_FUZZ_PRECISION");
  ASSERT_TRUE(in_precision_family(in));
  // Copies of one vertex (theta 281 % 8 = vertex 1, at (12, 0)), 2 + grid 12 % 3 = 2 of them, moved apart.
  ASSERT_EQ(in.vertices.size(), 10u);
  EXPECT_EQ(in.vertices[8].x, 12);
  EXPECT_EQ(in.vertices[9].y, 0);
  const lepp::Pslg pslg = to_pslg(in);
  ASSERT_EQ(pslg.vertices.size(), 10u);
  const lepp::Point a = pslg.vertices[1], b = pslg.vertices[8], c = pslg.vertices[9];
  EXPECT_FALSE(a.x == b.x && a.y == b.y);
  EXPECT_FALSE(b.x == c.x && b.y == c.y);
  EXPECT_LE(std::abs(b.x - a.x), 4 * (std::nextafter(a.x, 1e300) - a.x)) << "a few ulps, no more";
  // Without the variable the input is left as it is.
  FuzzInput plain = square_with_hole();
  apply_environment(plain);
  EXPECT_FALSE(in_precision_family(plain));
  // Encoded, the cluster replays without the variable (what fuzz_make_seeds --bake relies on).
  const std::vector<std::uint8_t> bytes = encode(in);
  EXPECT_EQ(describe(decode(bytes.data(), bytes.size())), describe(in));
}

TEST(FuzzInput, PrecisionCampaignMutationsStayInTheFamily) {
  ::setenv("LEPP_FUZZ_PRECISION", "1", 1);
  std::mt19937 rng(11);
  int clusters = 0;
  for (int i = 0; i < 200; ++i) {  // one edit of a fresh input each time: about 1 in 2 (1 in 8 without the variable)
    FuzzInput in = square_with_hole();
    mutate(in, rng);
    clusters += in_precision_family(in);
  }
  ::unsetenv("LEPP_FUZZ_PRECISION");
  EXPECT_GT(clusters, 60) << "every other edit is a cluster or an offset";
}

TEST(FuzzInput, ToPslgDropsCrossingAndThroughVertexSegments) {
  FuzzInput in;
  in.grid = 4;
  in.vertices = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  in.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}, {1, 3}, {2, 0}};  // (1,3) crosses (0,2); (2,0) repeats it
  EXPECT_EQ(to_pslg(in).segments.size(), 5u);
  in.vertices.push_back({2, 2});  // now (0,2) passes through vertex 4, and (1,3) is kept instead
  EXPECT_EQ(to_pslg(in).segments.size(), 4u);
}

TEST(LoopGuard, BudgetAndFloorFollowTheLocalFeatureSize) {
  lepp::Pslg pslg;
  pslg.vertices = {{0, 0}, {8, 0}, {8, 8}, {0, 8}, {4, 0.5}};
  pslg.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  const InputFeatures f = input_features(pslg);
  EXPECT_DOUBLE_EQ(f.lfs_min, 0.5);  // vertex 4 to segment 0
  EXPECT_NEAR(f.min_input_angle_deg, 90, 1e-9);
  const LoopGuard g = loop_guard(pslg, 1 << 30);
  EXPECT_EQ(g.steiner_budget, 64 * 9 + 16 * 64 * 4);
  EXPECT_DOUBLE_EQ(g.edge_floor, 0.5 / 1024);
  EXPECT_NEAR(alpha_limit_deg(), 22.24, 0.01);
}

TEST(LoopGuard, ClassifiesASelfSimilarMidpointSequenceAsTheSpecialLoop) {
  // A fake traced run: the same bad triangle shape, halving, ten times.
  lepp::Pslg pslg;
  pslg.vertices = {{0, 0}, {100, 0}, {0, 100}};
  pslg.segments = {{0, 1}, {1, 2}, {2, 0}};
  lepp::RefineResult traced;
  traced.mesh.vertices = pslg.vertices;
  for (int k = 0; k < 10; ++k) {
    const double s = std::ldexp(1.0, -k);
    const int base = static_cast<int>(traced.mesh.vertices.size());
    traced.mesh.vertices.push_back({10 + 20 * s, 10});
    traced.mesh.vertices.push_back({10 + 40 * s, 10});
    traced.mesh.vertices.push_back({10 + 25 * s, 10 + 6 * s});
    lepp::TraceStep step;
    step.bad = {base, base + 1, base + 2};
    traced.trace.push_back(step);
  }
  traced.mesh.triangles = {{0, 1, 2}};
  lepp::RefineOptions options;
  options.method = lepp::Method::Midpoint;
  options.min_angle_deg = 25;
  EXPECT_EQ(classify_loop(pslg, options, traced), "midpoint-special-loop");
  options.method = lepp::Method::Centroid;
  EXPECT_EQ(classify_loop(pslg, options, traced), "self-similar-loop");
  traced.trace.resize(2);  // too short to repeat
  EXPECT_EQ(classify_loop(pslg, options, traced), "other");
}

TEST(LoopGuard, ClassifiesShortEdgesAtASmallInputAngleAsACascade) {
  lepp::Pslg pslg;
  pslg.vertices = {{0, 0}, {100, 0}, {100, 10}};  // about 5.7 degrees at vertex 0
  pslg.segments = {{0, 1}, {1, 2}, {2, 0}};
  lepp::RefineResult traced;
  traced.mesh.vertices = pslg.vertices;
  traced.mesh.vertices.push_back({1e-3, 0});
  traced.mesh.vertices.push_back({1e-3, 1e-4});
  traced.mesh.triangles = {{0, 3, 4}, {3, 1, 2}, {3, 2, 4}};
  lepp::RefineOptions options;
  EXPECT_EQ(classify_loop(pslg, options, traced), "small-angle-cascade");
}

TEST(Finding, ThrowsInReplayExpectMode) {
  set_expect_findings(true);
  EXPECT_THROW(report_finding("test", "some-class", "a message"), FindingReported);
  set_expect_findings(false);
}

// Which loops stop a run: those inside the bands the paper proves.
TEST(KnownLoops, LoopsInsideTheProvenBandsStillStopTheRun) {
  using lepp::Method;
  EXPECT_EQ(unclaimed_loop_reason(Method::Centroid, 30.0, "self-similar-loop"), "");
  EXPECT_EQ(unclaimed_loop_reason(Method::Centroid, 20.0, "other"), "");
  EXPECT_EQ(unclaimed_loop_reason(Method::Midpoint, 22.2, "other"), "");
  EXPECT_EQ(unclaimed_loop_reason(Method::Midpoint, 10.0, "self-similar-loop"), "");
}

TEST(KnownLoops, LoopsOutsideThePapersClaimsAreKnown) {
  using lepp::Method;
  EXPECT_EQ(unclaimed_loop_reason(Method::Centroid, 30.1, "self-similar-loop"), "centroid-above-30");
  EXPECT_EQ(unclaimed_loop_reason(Method::Centroid, 36.0, "other"), "centroid-above-30");
  EXPECT_EQ(unclaimed_loop_reason(Method::Midpoint, 22.3, "midpoint-special-loop"), "midpoint-above-alpha-limit");
  EXPECT_EQ(unclaimed_loop_reason(Method::Midpoint, 29.9, "other"), "midpoint-above-alpha-limit");
  // A cascade at a small input angle is outside every claim, at any theta.
  EXPECT_EQ(unclaimed_loop_reason(Method::Centroid, 15.0, "small-angle-cascade"), "small-input-angle");
  EXPECT_EQ(unclaimed_loop_reason(Method::Midpoint, 15.0, "small-angle-cascade"), "small-input-angle");
}

// Inputs doubles do not resolve (THEOREMS.md, "Termination in doubles"): a feature
// below 2^-40 of the largest coordinate magnitude. At the boundary: 2^-40 exactly is
// resolved, one step below is not; a subnormal feature (the floor underflows) is not.
TEST(KnownLoops, FeaturesBelowResolutionAtTheBoundary) {
  auto square_with = [](double x, double y) {
    lepp::Pslg p;
    p.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {x, y}};
    p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}, {3, 0, 0}};
    return p;
  };
  EXPECT_EQ(below_resolution_reason(square_with(0.5, 0.5)), "");
  EXPECT_EQ(below_resolution_reason(square_with(0.5, std::ldexp(1.0, -40))), "");  // 2^-40 from the side y = 0
  EXPECT_EQ(below_resolution_reason(square_with(0.5, std::ldexp(1.0, -41))), "feature-below-resolution");
  EXPECT_EQ(below_resolution_reason(square_with(0.5, 5e-324)), "feature-below-resolution");
  // Scale does not matter: the same square at 2^40.
  lepp::Pslg big = square_with(0.5, std::ldexp(1.0, -41));
  for (lepp::Point& v : big.vertices) v = {v.x * 0x1p40, v.y * 0x1p40};
  EXPECT_EQ(below_resolution_reason(big), "feature-below-resolution");
}

// The certificate's text for the fuzz targets: the documented undecided class only
// when every violation is an undecided precision claim.
TEST(CertifyResultText, PrecisionUndecidedIsRecognisedByItsPrefix) {
  EXPECT_TRUE(precision_undecided(std::string(kPrecisionUndecided) + "[unimprovable-rule-fails] ..."));
  EXPECT_FALSE(precision_undecided("[unimprovable-rule-fails] ... can be inserted"));
  EXPECT_FALSE(precision_undecided(""));
}

TEST(KnownLoops, BandsAndKeysNameMethodClassAndBand) {
  EXPECT_EQ(band_label(20.7), "10-20.7");
  EXPECT_EQ(band_label(22.2), "20.8-22.2");
  EXPECT_EQ(band_label(30.0), "22.3-30");
  EXPECT_EQ(band_label(30.1), "30.1-36");
  EXPECT_EQ(known_finding_key("fuzz_refine", "loop-other", lepp::Method::Midpoint, 33.0),
            "fuzz_refine-loop-other-midpoint-theta30.1-36");
}

namespace {
std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  std::filesystem::remove_all(dir);
  return dir;
}
std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
}  // namespace

TEST(KnownLoops, KeepsOneExamplePerKey) {
  const auto dir = fresh_dir("lepp-known-keep");
  const std::uint8_t first[] = {1, 2, 3}, second[] = {9, 9};
  const std::string kept = keep_known_example(dir.string(), "k", first, sizeof first, "first message");
  EXPECT_EQ(kept, (dir / "k.bin").string());
  EXPECT_EQ(slurp(dir / "k.bin"), std::string("\1\2\3", 3));
  EXPECT_EQ(slurp(dir / "k.txt"), "first message\n");
  EXPECT_EQ(keep_known_example(dir.string(), "k", second, sizeof second, "second"), "");  // not overwritten
  EXPECT_EQ(slurp(dir / "k.bin"), std::string("\1\2\3", 3));
  EXPECT_NE(keep_known_example(dir.string(), "other-key", second, sizeof second, "x"), "");
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) files += entry.is_regular_file();
  EXPECT_EQ(files, 4u);  // two .bin, two .txt, no temporary left over
  std::filesystem::remove_all(dir);
}

TEST(KnownLoops, AKnownFindingReturnsAndKeepsTheInput) {
  const auto dir = fresh_dir("lepp-known-report");
  ::setenv("LEPP_FUZZ_KNOWN_DIR", dir.c_str(), 1);
  const std::uint8_t data[] = {7, 7, 7};
  set_expect_findings(false);  // as under libFuzzer: report_finding would abort here
  report_known_finding("fuzz_refine", "loop-other", "centroid-above-30", "key", "msg", data, sizeof data);
  report_known_finding("fuzz_refine", "loop-other", "centroid-above-30", "key", "msg", data, sizeof data);
  EXPECT_TRUE(std::filesystem::exists(dir / "key.bin"));
  ::unsetenv("LEPP_FUZZ_KNOWN_DIR");
  std::filesystem::remove_all(dir);
}

TEST(KnownLoops, AKnownFindingStillCountsWhenReplayingOpenRegressions) {
  set_expect_findings(true);
  const std::uint8_t data[] = {1};
  EXPECT_THROW(report_known_finding("fuzz_refine", "loop-other", "centroid-above-30", "key", "msg", data, 1),
               FindingReported);
  set_expect_findings(false);
}

TEST(KnownLoops, AnUnknownFindingStillStopsTheRun) {
  set_expect_findings(false);
  EXPECT_DEATH(report_finding("fuzz_refine", "loop-self-similar-loop", "a loop at theta 25"), "LEPP-FINDING");
}

TEST(CgalCdt, SquareWithHoleHasEightTriangles) {
  const CgalCdt cdt = cgal_cdt(to_pslg(square_with_hole()));
  EXPECT_EQ(cdt.mesh.triangles.size(), 8u);
  EXPECT_EQ(cdt.mesh.constrained_edges.size(), 8u);
}

class CertifyResult : public ::testing::Test {
 protected:
  lepp::Pslg pslg = to_pslg(square_with_hole());
  lepp::Mesh mesh = cgal_cdt(pslg).mesh;
};

TEST_F(CertifyResult, AcceptsTheCdt) { EXPECT_EQ(certify_problems(pslg, mesh, 0, {}), ""); }

TEST_F(CertifyResult, RejectsAVertexIdOutOfRange) {
  mesh.triangles[0][1] = 99;
  EXPECT_NE(certify_problems(pslg, mesh, 0, {}), "");
}

TEST_F(CertifyResult, RejectsAMovedInputVertex) {
  mesh.vertices[4].x += 0.25;
  EXPECT_NE(certify_problems(pslg, mesh, 0, {}), "");
}

TEST_F(CertifyResult, RejectsAMeshedHole) {
  if (!have_certifier()) GTEST_SKIP() << "certifier not built";
  mesh.triangles.push_back({4, 5, 6});
  EXPECT_NE(certify_problems(pslg, mesh, 0, {}), "");
}

TEST_F(CertifyResult, RejectsAnAngleBelowTheta) {
  if (!have_certifier()) GTEST_SKIP() << "certifier not built";
  EXPECT_NE(certify_problems(pslg, mesh, 30, {}), "");  // the CDT has angles of about 26.6 degrees
}

// fuzz_differential takes the fast run's verdict for the reference's only when the
// certifier could not tell the two results apart: any field it reads differs, no.
TEST_F(CertifyResult, SameCertifierInputSeesEveryFieldTheCertifierReads) {
  lepp::RefineResult a;
  a.mesh = mesh;
  a.outcome = lepp::Outcome::Unimprovable;
  lepp::UnimprovableTriangle left;
  left.triangle = mesh.triangles[0];
  left.reason = lepp::LeftReason::DoublePrecision;
  left.point = {0.5, 0.5};
  a.unimprovable.push_back(left);
  lepp::RefineResult b = a;
  b.outcome = lepp::Outcome::Converged;  // claims theta as well
  b.steiner_points = 7;                  // not read by the certifier
  EXPECT_TRUE(same_certifier_input(a, b));
  const std::vector<std::function<void(lepp::RefineResult&)>> edits = {
      [](lepp::RefineResult& r) { r.outcome = lepp::Outcome::SteinerBudget; },
      [](lepp::RefineResult& r) { r.mesh.vertices[5].x = std::nextafter(r.mesh.vertices[5].x, 9.0); },
      [](lepp::RefineResult& r) { r.mesh.input_vertices -= 1; },
      [](lepp::RefineResult& r) { std::swap(r.mesh.triangles[0], r.mesh.triangles[1]); },
      [](lepp::RefineResult& r) { r.mesh.constrained_edges[0].segment += 1; },
      [](lepp::RefineResult& r) { r.mesh.constrained_edges.pop_back(); },
      [](lepp::RefineResult& r) { r.unimprovable.clear(); },
      [](lepp::RefineResult& r) { r.unimprovable[0].reason = lepp::LeftReason::SmallInputAngle; },
      [](lepp::RefineResult& r) { r.unimprovable[0].point.y = 0.25; },
      [](lepp::RefineResult& r) { r.unimprovable[0].rule = lepp::Rule::TerminalMidpoint; },
      [](lepp::RefineResult& r) { r.unimprovable[0].segment2 = 3; },
  };
  for (std::size_t i = 0; i < edits.size(); ++i) {
    lepp::RefineResult c = a;
    edits[i](c);
    EXPECT_FALSE(same_certifier_input(a, c)) << "edit " << i;
    EXPECT_FALSE(same_certifier_input(c, a)) << "edit " << i;
  }
}
