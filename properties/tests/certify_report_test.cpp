// SPDX-License-Identifier: GPL-3.0-or-later
// The certifier's names and its text report: every check and reason has a name of
// its own (the report and `lepp certify --json` print them), the exempt list is
// capped with a count of the rest, and engine-listed unimprovable triangles that
// pass the rule are summed up on a line of their own.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <set>
#include <string>

#include "certify_test_support.h"
#include "cgal_mesh.h"
#include "lepp/certify.h"
#include "lepp/validate.h"
#include "test_pslgs.h"

namespace lepp {
namespace {

using certify::Check;
using certify::Reason;

constexpr int kChecks = static_cast<int>(Check::SizeBound) + 1;              // the last Check
constexpr int kReasons = static_cast<int>(Reason::AreaAboveBound) + 1;        // the last Reason

TEST(CertifyNames, EveryCheckHasItsOwnName) {
  std::set<std::string> names;
  for (int c = 0; c < kChecks; ++c) {
    const std::string name = certify::to_string(static_cast<Check>(c));
    EXPECT_FALSE(name.empty()) << "check " << c;
    EXPECT_NE(name, "?") << "check " << c;
    EXPECT_TRUE(names.insert(name).second) << "check " << c << " repeats the name " << name;
  }
}

TEST(CertifyNames, EveryReasonHasItsOwnNameAndBelongsToACheck) {
  std::set<std::string> names;
  std::set<int> checks_used;
  for (int r = 0; r < kReasons; ++r) {
    const Reason reason = static_cast<Reason>(r);
    const std::string name = certify::to_string(reason);
    EXPECT_FALSE(name.empty()) << "reason " << r;
    EXPECT_NE(name, "?") << "reason " << r;
    EXPECT_TRUE(names.insert(name).second) << "reason " << r << " repeats the name " << name;
    checks_used.insert(static_cast<int>(certify::check_of(reason)));
  }
  EXPECT_EQ(checks_used.size(), static_cast<std::size_t>(kChecks)) << "a check with no reason of its own";
  // A few reasons pinned to their group, as lepp/certify.h groups them.
  EXPECT_EQ(certify::check_of(Reason::DuplicateMeshVertex), Check::Topology);
  EXPECT_EQ(certify::check_of(Reason::InputVertexMoved), Check::InputVertices);
  EXPECT_EQ(certify::check_of(Reason::ConstrainedEdgeUnlisted), Check::Constraints);
  EXPECT_EQ(certify::check_of(Reason::ConstrainedEdgeWrongSegment), Check::Constraints);
  EXPECT_EQ(certify::check_of(Reason::NotLocallyDelaunay), Check::Delaunay);
  EXPECT_EQ(certify::check_of(Reason::UnimprovableRuleFails), Check::MinAngle);
  EXPECT_EQ(certify::check_of(Reason::TerminalAngleOver120), Check::Theorem2);
  EXPECT_EQ(certify::check_of(Reason::AreaAboveBound), Check::SizeBound);
}

TEST(CertifyReport, CountOfAReportNotFilledIsZero) {
  // count() reads past count_by_reason (empty before certify() fills it) as zero.
  const certify::Report r;
  for (int k = 0; k < kReasons; ++k) EXPECT_EQ(r.count(static_cast<Reason>(k)), 0u) << k;
  certify::Report filled;
  filled.count_by_reason.assign(kReasons, 0);
  filled.count_by_reason[static_cast<std::size_t>(Reason::EdgeOverused)] = 3;
  EXPECT_EQ(filled.count(Reason::EdgeOverused), 3u);
  EXPECT_TRUE(filled.has(Reason::EdgeOverused));
  EXPECT_FALSE(filled.certified());
}

// A saw of `teeth` teeth on a block of unit squares: each tooth (k,0) (k+1,0)
// (k+1/2,3) has an input angle of about 18.9 degrees at its tip, and its CDT is
// one triangle with that angle; the block is right isosceles triangles.
Pslg saw(int teeth) {
  Pslg p;
  for (int k = 0; k <= teeth; ++k) p.vertices.push_back({static_cast<double>(k), -1});  // 0..teeth: the bottom
  for (int k = 0; k <= teeth; ++k) p.vertices.push_back({static_cast<double>(k), 0});   // the valleys
  for (int k = 0; k < teeth; ++k) p.vertices.push_back({k + 0.5, 3});                   // the tips
  const int valley = teeth + 1, tip = 2 * teeth + 2;
  for (int k = 0; k < teeth; ++k) p.segments.push_back({k, k + 1, 0});  // the bottom side
  p.segments.push_back({teeth, 2 * teeth + 1, 0});                      // the right side
  for (int k = teeth; k > 0; --k) {                                    // the teeth, right to left
    p.segments.push_back({valley + k, tip + k - 1, 0});
    p.segments.push_back({tip + k - 1, valley + k - 1, 0});
  }
  p.segments.push_back({valley, 0, 0});  // the left side
  return test::validated(p);
}

TEST(CertifyReport, ExemptListIsCappedWithACountOfTheRest) {
  const int teeth = 13;
  const Pslg p = saw(teeth);
  const Mesh m = test::cgal_cdt(p);
  certify::Options options;
  options.min_angle_deg = 20;
  const auto plain = certify::certify(p, m, options);
  ASSERT_EQ(plain.count(Reason::AngleBelowTheta), static_cast<std::size_t>(teeth)) << certify::format_report(plain);
  options.exempt_small_input_angles = true;
  const auto r = certify::certify(p, m, options);
  ASSERT_TRUE(r.certified()) << certify::format_report(r);
  ASSERT_EQ(r.exempt_count, static_cast<std::size_t>(teeth));
  const std::string text = certify::format_report(r);
  EXPECT_NE(text.find(std::to_string(teeth) + " triangles below theta exempt"), std::string::npos) << text;
  // Ten named, the other three counted.
  std::size_t named = 0;
  for (std::size_t at = text.find("  exempt: triangle "); at != std::string::npos; at = text.find("  exempt: triangle ", at + 1)) ++named;
  EXPECT_EQ(named, 10u) << text;
  EXPECT_NE(text.find("  ... and " + std::to_string(teeth - 10) + " more exempt triangles\n"), std::string::npos) << text;
  // At the cap itself nothing is left over to count.
  const Pslg q = saw(10);
  const auto ten = certify::certify(q, test::cgal_cdt(q), options);
  ASSERT_EQ(ten.exempt_count, 10u) << certify::format_report(ten);
  EXPECT_EQ(certify::format_report(ten).find("more exempt triangles"), std::string::npos) << certify::format_report(ten);
}

TEST(CertifyReport, AcceptedUnimprovableTrianglesAreSummedUp) {
  // One triangle, listed unimprovable.
  const auto [p, m] = test::ten_degree_wedge();
  certify::Options options;
  options.min_angle_deg = 20;
  const std::string line = "1 triangles below theta accepted as unimprovable";
  EXPECT_EQ(certify::format_report(certify::certify(p, m, options)).find(line), std::string::npos);
  options.unimprovable = {{{0, 1, 2}, 0, 0, 1, 10}};
  const auto r = certify::certify(p, m, options);
  ASSERT_TRUE(r.certified()) << certify::format_report(r);
  ASSERT_EQ(r.unimprovable_accepted.size(), 1u);
  EXPECT_NE(certify::format_report(r).find(line), std::string::npos) << certify::format_report(r);
}

}  // namespace
}  // namespace lepp
