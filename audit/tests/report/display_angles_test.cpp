// SPDX-License-Identifier: GPL-3.0-or-later
// The angles a finding shows are right at any magnitude (issue 19: at 1e299 and
// 1e-301 they read "about 45 degrees", "about 0", "nan" while the exact verdicts
// were right): lepp::angle_deg scales its vectors, the certifier's messages and
// the termination row's input-angle class use it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "lepp/certify.h"
#include "lepp/gen.h"
#include "lepp/stats.h"

namespace lepp {
namespace {

// The number after "(about " in a certifier message.
double about(const std::string& message) {
  const std::size_t at = message.find("(about ");
  if (at == std::string::npos) return NAN;
  return std::strtod(message.c_str() + at + 7, nullptr);
}

Point scaled(Point p, double s) { return {p.x * s, p.y * s}; }

const double kScales[] = {1, 1e299, 1e-301, 1e-310};  // the last: subnormal coordinates

TEST(DisplayAngles, AngleDegAtAnyMagnitude) {
  const double t = std::tan(10 * M_PI / 180) / 2;
  for (double s : kScales) {
    const Point a = scaled({0, 0}, s), b = scaled({1, 0}, s), c = scaled({0.5, t}, s);
    EXPECT_NEAR(angle_deg(a, b, c), 10, 1e-6) << "scale " << s;
    EXPECT_NEAR(angle_deg(c, a, b), 160, 1e-6) << "scale " << s;
    EXPECT_NEAR(min_angle_deg(a, b, c), 10, 1e-6) << "scale " << s;
    EXPECT_NEAR(signed_angle_deg(a, c, b), -10, 1e-6) << "scale " << s;
  }
  // Differences past DBL_MAX: the vectors are taken of the halves.
  EXPECT_NEAR(angle_deg({-1e308, 0}, {1e308, 0}, {-1e308, 1.7e308}), 90, 1e-9);
  // The broken arithmetic this replaces: the products overflow to nan, underflow to 0.
  const double ux = 1e299, vy = 1e299;
  EXPECT_TRUE(std::isinf(ux * vy));
}

TEST(DisplayAngles, CertifierMessagesAtAnyMagnitude) {
  const double t = std::tan(10 * M_PI / 180) / 2;
  for (double s : kScales) {
    Pslg p;
    p.vertices = {scaled({0, 0}, s), scaled({1, 0}, s), scaled({0.5, t}, s)};
    p.segments = {{0, 1}, {1, 2}, {2, 0}};
    Mesh m;
    m.vertices = p.vertices;
    m.triangles = {{{0, 1, 2}}};
    certify::Options o;
    o.min_angle_deg = 20;
    const certify::Report r = certify::certify(p, m, o);
    bool seen = false;
    for (const certify::Violation& v : r.violations)
      if (v.reason == certify::Reason::AngleBelowTheta) {
        seen = true;
        EXPECT_NEAR(about(v.message), 10, 1e-6) << "scale " << s << ": " << v.message;
      }
    EXPECT_TRUE(seen) << "scale " << s;
    EXPECT_NEAR(gen::min_input_angle_deg(p), 10, 1e-6) << "scale " << s;
  }
  // Theorem 2: a terminal edge whose apex angle is about 157.38 degrees.
  for (double s : kScales) {
    Pslg p;
    p.vertices = {scaled({0, 0}, s), scaled({2, 0}, s), scaled({1, 0.2}, s), scaled({1, -1}, s)};
    p.segments = {{0, 2}, {2, 1}, {1, 3}, {3, 0}};
    Mesh m;
    m.vertices = p.vertices;
    m.triangles = {{{0, 1, 2}}, {{1, 0, 3}}};
    certify::Options o;
    o.theorem2 = true;
    const certify::Report r = certify::certify(p, m, o);
    bool seen = false;
    const double want = std::acos((-1 + 0.04) / 1.04) * 180 / M_PI;
    for (const certify::Violation& v : r.violations)
      if (v.reason == certify::Reason::TerminalAngleOver120) {
        seen = true;
        EXPECT_NEAR(about(v.message), want, 1e-6) << "scale " << s << ": " << v.message;
      }
    EXPECT_TRUE(seen) << "scale " << s;
  }
}

}  // namespace
}  // namespace lepp
