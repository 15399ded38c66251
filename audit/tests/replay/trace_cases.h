// SPDX-License-Identifier: GPL-3.0-or-later
// Traces the replay's white-box tests share: eleven cases (meshes at the origin,
// far from it and at subnormal scale, either reading's centroid, the paper's A, the
// precision corpus), the points asked at a step (on the choice, a few ulps to far
// off it, on vertices, between choices, far away), and a replay of a trace on two
// replayers that must answer every question the same (a search with and without
// a shortcut: replay_far_tests).
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../../src/replay/replayer.h"
#include "lepp/fast.h"
#include "lepp/io.h"
#include "lepp/validate.h"

namespace lepp::audit::replay_detail::trace_cases {

inline Pslg read_corpus(const std::string& rel) {
  std::vector<std::string> warnings;
  const std::string path = std::string(LEPP_SOURCE_DIR "/corpus/") + rel;
  return validate(rel.size() > 5 && rel.substr(rel.size() - 5) == ".node" ? read_node(path) : read_poly(path), warnings);
}

// The PSLG moved by (dx, dy) and scaled by s (each coordinate rounded).
inline Pslg moved(Pslg p, double s, double dx, double dy) {
  for (Point& v : p.vertices) v = {v.x * s + dx, v.y * s + dy};
  for (Point& h : p.holes) h = {h.x * s + dx, h.y * s + dy};
  for (Region& r : p.regions) r.at = {r.at.x * s + dx, r.at.y * s + dy};
  std::vector<std::string> warnings;
  return validate(p, warnings);
}

inline Pslg square() {
  Pslg p;
  p.vertices = {{0, 0}, {1, 0}, {1, 0.3}, {0, 1}, {0.4, 0.55}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}, {3, 0, 0}};
  std::vector<std::string> warnings;
  return validate(p, warnings);
}

struct Case {
  std::string name;
  Pslg pslg;
  Method method;
  double theta;
  // The area reading with the vertex centroid allowed (the fast engine's): the
  // paper's choices then have the area scale, and the trace still replays.
  bool area = false;
  // The vertex reading with the area centroid allowed (a program's other reading):
  // the catalogue is asked in the search around each point.
  bool allow_area = false;
};

inline std::vector<Case> cases() {
  return {
      {"square centroid", square(), Method::Centroid, 28},
      {"square far from the origin", moved(square(), 1, 1e6, -3e5), Method::Centroid, 25},
      {"square, area reading", square(), Method::Centroid, 28, true},
      {"square, the area centroid allowed", square(), Method::Centroid, 28, false, true},
      {"square far from the origin, area reading", moved(square(), 1, 1e6, -3e5), Method::Centroid, 25, true},
      {"square at subnormal scale", moved(square(), 0x1p-1060, 0, 0), Method::Centroid, 25},
      {"A midpoint", read_corpus("paper/A.poly"), Method::Midpoint, 20},
      {"notch-2e20", read_corpus("regressions/precision/notch-2e20.poly"), Method::Centroid, 25},
      {"midpoint-past-sliver", read_corpus("regressions/precision/midpoint-past-sliver.poly"), Method::Centroid, 13.9},
      {"circles240", read_corpus("paper/circles240.poly"), Method::Centroid, 28},
      {"second-longest tie", read_corpus("regressions/precision/notch-second-longest-tie.poly"), Method::Centroid, 30},
  };
}

inline double ulps(double x, int k) {
  for (; k > 0; --k) x = std::nextafter(x, INFINITY);
  return x;
}

// Points asked about at a step: the choice itself, a few ulps to far off it, on an
// input vertex, between two choices, far outside.
inline std::vector<Point> probes(const std::vector<TraceStep>& trace, std::size_t i, const Pslg& pslg) {
  const Point p = trace[i].point;
  const double s = std::max(std::abs(p.x), std::abs(p.y));
  const Point q = trace[(i + 1) % trace.size()].point;
  return {p,
          {ulps(p.x, 3), p.y},
          {p.x, ulps(p.y, 300)},
          {p.x + 1e-9 * s, p.y - 1e-9 * s},
          {p.x + 1e-3 * s, p.y},
          pslg.vertices[i % pslg.vertices.size()],
          {(p.x + q.x) / 2, (p.y + q.y) / 2},
          {p.x + 1e3 * s, p.y - 1e3 * s}};
}

inline void expect_same(const ReplayChoice& a, const ReplayChoice& b, const std::string& where) {
  EXPECT_EQ(a.bad, b.bad) << where;
  EXPECT_EQ(a.lepp, b.lepp) << where;
  EXPECT_EQ(a.terminal_edge, b.terminal_edge) << where;
  EXPECT_EQ(a.t1, b.t1) << where;
  EXPECT_EQ(a.t2, b.t2) << where;
  EXPECT_EQ(a.rule, b.rule) << where;
  EXPECT_EQ(a.point.x, b.point.x) << where;
  EXPECT_EQ(a.point.y, b.point.y) << where;
  EXPECT_EQ(a.distance, b.distance) << where;
  EXPECT_EQ(a.tolerance, b.tolerance) << where;
  EXPECT_EQ(a.split_edge, b.split_edge) << where;
  EXPECT_EQ(a.deviation, b.deviation) << where;
}

inline RefineResult traced_run(const Case& c) {
  RefineOptions options;
  options.method = c.method;
  options.min_angle_deg = c.theta;
  options.max_steiner = 80;
  options.trace = true;
  return fast::refine(c.pslg, options);
}

inline ReplayRules rules_of(const Case& c) {
  ReplayRules rules;
  rules.method = c.method;
  rules.min_angle_deg = c.theta;
  if (c.area) {
    rules.centroid = CentroidReading::Area;
    rules.variant = Deviation::VertexCentroid;
  }
  if (c.allow_area) rules.variant = Deviation::AreaCentroid;
  return rules;
}

// Replays c's trace (run) on a and b, asking both, at every fourth step, what
// probes() asks (diagnose, and match where the point is not the step's own), and
// at every step its point (match, then insert). on(true) is called before each of
// a's calls, on(false) before b's: the switches that make the two differ.
// Returns the steps replayed (all of them, unless the two disagree).
template <class Switch>
std::size_t replay_both(const Case& c, const RefineResult& run, Replayer& a, Replayer& b, Switch on) {
  std::size_t replayed = 0;
  for (std::size_t i = 0; i < run.trace.size(); ++i) {
    if (i % 4 == 0)
      for (const Point& p : probes(run.trace, i, c.pslg)) {
        const std::string where = c.name + ", step " + std::to_string(i + 1) + ", (" + std::to_string(p.x) + ", " +
                                  std::to_string(p.y) + ")";
        on(true);
        const DeviationMatch da = a.diagnose(p);
        on(false);
        const DeviationMatch db = b.diagnose(p);
        EXPECT_EQ(da.deviation, db.deviation) << where;
        EXPECT_EQ(da.what, db.what) << where;
        expect_same(da.where, db.where, where);
        EXPECT_EQ(da.paper.size(), db.paper.size()) << where;
        if (da.paper.size() != db.paper.size()) return replayed;
        for (std::size_t k = 0; k < da.paper.size(); ++k) expect_same(da.paper[k], db.paper[k], where);
        if (p.x == run.trace[i].point.x && p.y == run.trace[i].point.y) continue;  // matched below
        ReplayChoice ca, cb;
        on(true);
        const bool ma = a.match(p, ca);
        on(false);
        const bool mb = b.match(p, cb);
        EXPECT_EQ(ma, mb) << where;
        if (ma != mb) return replayed;
        if (ma) expect_same(ca, cb, where);
      }
    const Point& p = run.trace[i].point;
    ReplayChoice ca, cb;
    on(true);
    const bool ma = a.match(p, ca);
    on(false);
    const bool mb = b.match(p, cb);
    EXPECT_EQ(ma, mb) << c.name << ", step " << i + 1;
    if (!ma || !mb) break;
    expect_same(ca, cb, c.name + ", step " + std::to_string(i + 1));
    on(true);
    a.insert(p, ca);
    on(false);
    b.insert(p, cb);
    ++replayed;
  }
  return replayed;
}

}  // namespace lepp::audit::replay_detail::trace_cases
