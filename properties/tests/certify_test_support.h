// SPDX-License-Identifier: GPL-3.0-or-later
// What the certifier's tests share: running the certifier at a theta, reading a
// report (counts, messages, the first violation of a reason) and asserting on it,
// and the hand-made meshes more than one test file needs.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "lepp/certify.h"
#include "lepp/mesh.h"
#include "lepp/pslg.h"

namespace lepp::test {

inline certify::Report run(const Pslg& pslg, const Mesh& mesh, double theta = 0) {
  certify::Options options;
  options.min_angle_deg = theta;
  return certify::certify(pslg, mesh, options);
}

// Violations of every reason, counted before the per-kind cap.
inline std::size_t total(const certify::Report& r) {
  std::size_t n = 0;
  for (std::size_t c : r.count_by_reason) n += c;
  return n;
}

// The messages of the listed violations of one reason.
inline std::vector<std::string> messages(const certify::Report& r, certify::Reason reason) {
  std::vector<std::string> out;
  for (const certify::Violation& v : r.violations)
    if (v.reason == reason) out.push_back(v.message);
  return out;
}

inline const certify::Violation* first_of(const certify::Report& r, certify::Reason reason) {
  for (const certify::Violation& v : r.violations)
    if (v.reason == reason) return &v;
  return nullptr;
}

inline void expect_certified(const certify::Report& r) { EXPECT_TRUE(r.certified()) << certify::format_report(r); }

// Rejected, for this reason among others, with a message that says something.
inline void expect_rejected_for(const certify::Report& r, certify::Reason reason) {
  EXPECT_FALSE(r.certified());
  EXPECT_TRUE(r.has(reason)) << "expected " << certify::to_string(reason) << "\n" << certify::format_report(r);
  const certify::Violation* v = first_of(r, reason);
  ASSERT_NE(v, nullptr);
  EXPECT_FALSE(v->message.empty());
}

// Rejected for this reason exactly n times (other reasons may come too).
inline void expect_rejected_times(const certify::Report& r, certify::Reason reason, std::size_t n) {
  expect_rejected_for(r, reason);
  EXPECT_EQ(r.count(reason), n) << certify::format_report(r);
}

// Rejected for exactly one violation, of this reason (a mutation that breaks one thing).
inline void expect_rejected_only_for(const certify::Report& r, certify::Reason reason) {
  expect_rejected_for(r, reason);
  EXPECT_EQ(r.count(reason), 1u) << certify::format_report(r);
  EXPECT_EQ(total(r), r.count(reason)) << "other reasons too:\n" << certify::format_report(r);
}

// A 10-degree wedge between segments 0 (v0-v1) and 1 (v0-v2), closed by segment 2,
// meshed as its single triangle, every edge listed: at theta 20 it is below theta,
// and unimprovable (its shortest edge v1-v2 joins the two segments of the wedge).
struct MeshedPslg {
  Pslg pslg;
  Mesh mesh;
};
inline MeshedPslg ten_degree_wedge() {
  const double rad = 10 * M_PI / 180;
  MeshedPslg w;
  w.pslg.vertices = {{0, 0}, {1, 0}, {std::cos(rad), std::sin(rad)}};
  w.pslg.segments = {{0, 1, 0}, {0, 2, 0}, {1, 2, 0}};
  w.mesh.vertices = w.pslg.vertices;
  w.mesh.input_vertices = 3;
  w.mesh.triangles = {{0, 1, 2}};
  w.mesh.constrained_edges = {{0, 1, 0}, {0, 2, 1}, {1, 2, 2}};
  return w;
}

}  // namespace lepp::test
