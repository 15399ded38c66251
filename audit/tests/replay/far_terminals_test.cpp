// SPDX-License-Identifier: GPL-3.0-or-later
// The whole-mesh searches skip a terminal configuration whose box of vertices lies
// farther from the program's point than any of its candidates' tolerances
// (Replayer::far_from, TerminalBound): white-box, the bound is checked against every
// candidate the catalogue and the paper make, and the searches' answers
// (match, diagnose with its list of nearest rules) are the same with the skip as
// without it, at points on the choices, a few ulps to far off them, on vertices and
// far away, on meshes at the origin, far from it and at subnormal scale.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../../src/replay/replayer.h"
#include "lepp/fast.h"
#include "lepp/io.h"
#include "lepp/validate.h"

namespace lepp::audit::replay_detail {
namespace {

Pslg read_corpus(const std::string& rel) {
  std::vector<std::string> warnings;
  const std::string path = std::string(LEPP_SOURCE_DIR "/corpus/") + rel;
  return validate(rel.size() > 5 && rel.substr(rel.size() - 5) == ".node" ? read_node(path) : read_poly(path), warnings);
}

// The PSLG moved by (dx, dy) and scaled by s (each coordinate rounded).
Pslg moved(Pslg p, double s, double dx, double dy) {
  for (Point& v : p.vertices) v = {v.x * s + dx, v.y * s + dy};
  for (Point& h : p.holes) h = {h.x * s + dx, h.y * s + dy};
  for (Region& r : p.regions) r.at = {r.at.x * s + dx, r.at.y * s + dy};
  std::vector<std::string> warnings;
  return validate(p, warnings);
}

Pslg square() {
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
};

std::vector<Case> cases() {
  return {
      {"square centroid", square(), Method::Centroid, 28},
      {"square far from the origin", moved(square(), 1, 1e6, -3e5), Method::Centroid, 25},
      {"square, area reading", square(), Method::Centroid, 28, true},
      {"square far from the origin, area reading", moved(square(), 1, 1e6, -3e5), Method::Centroid, 25, true},
      {"square at subnormal scale", moved(square(), 0x1p-1060, 0, 0), Method::Centroid, 25},
      {"A midpoint", read_corpus("paper/A.poly"), Method::Midpoint, 20},
      {"notch-2e20", read_corpus("regressions/precision/notch-2e20.poly"), Method::Centroid, 25},
      {"midpoint-past-sliver", read_corpus("regressions/precision/midpoint-past-sliver.poly"), Method::Centroid, 13.9},
      {"circles240", read_corpus("paper/circles240.poly"), Method::Centroid, 28},
      {"second-longest tie", read_corpus("regressions/precision/notch-second-longest-tie.poly"), Method::Centroid, 30},
  };
}

double ulps(double x, int k) {
  for (; k > 0; --k) x = std::nextafter(x, INFINITY);
  return x;
}

// Points asked about at a step: the choice itself, a few ulps to far off it, on an
// input vertex, between two choices, far outside.
std::vector<Point> probes(const std::vector<TraceStep>& trace, std::size_t i, const Pslg& pslg) {
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

void expect_same(const ReplayChoice& a, const ReplayChoice& b, const std::string& where) {
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

RefineResult traced_run(const Case& c) {
  RefineOptions options;
  options.method = c.method;
  options.min_angle_deg = c.theta;
  options.max_steiner = 80;
  options.trace = true;
  return fast::refine(c.pslg, options);
}

ReplayRules rules_of(const Case& c) {
  ReplayRules rules;
  rules.method = c.method;
  rules.min_angle_deg = c.theta;
  if (c.area) {
    rules.centroid = CentroidReading::Area;
    rules.variant = Deviation::VertexCentroid;
  }
  return rules;
}

// Every candidate at every terminal configuration of the mesh lies in the
// configuration's box no nearer than its lower bound, at a scale within its bound.
TEST(FarTerminals, TheBoundHoldsForEveryCandidate) {
  for (const Case& c : cases()) {
    const RefineResult run = traced_run(c);
    ASSERT_FALSE(run.trace.empty()) << c.name;
    Replayer replayer(c.pslg, rules_of(c));
    std::size_t checked = 0;
    for (std::size_t i = 0; i < run.trace.size(); i += 3) {
      const std::vector<Point> asked = probes(run.trace, i, c.pslg);
      for (FH f : replayer.tr.cdt.finite_face_handles()) {
        if (!in_domain(replayer.tr, f)) continue;
        for (int l = 0; l < 3; ++l) {
          FH n = f->neighbor(l);
          const bool has_t2 = !f->is_constrained(l) && !replayer.tr.cdt.is_infinite(n) && in_domain(replayer.tr, n);
          const Terminal t{f, has_t2 ? n : FH(), l};
          const TerminalBound b = terminal_bound(t);
          // The paper's choices at the rules' reading (vertex: no area scale), the
          // catalogue's at both.
          std::vector<std::pair<Candidate, double>> all;
          for (const Candidate& k : paper_candidates(replayer.rules, t)) all.push_back({k, c.area ? b.area_scale : b.scale});
          for (const Candidate& k : catalogue_points(replayer.rules, t)) all.push_back({k, b.area_scale});
          for (const auto& [k, scale] : all) {
            EXPECT_LE(k.scale, scale) << c.name;
            for (const Point& p : asked) {
              const double d = std::max(std::abs(CGAL::to_double(FT(p.x) - k.point.x())),
                                        std::abs(CGAL::to_double(FT(p.y) - k.point.y())));
              ASSERT_LE(b.box.lower_bound(p), d) << c.name << ": (" << p.x << ", " << p.y << ")";
              ++checked;
            }
          }
        }
      }
      ReplayChoice choice;
      if (!replayer.match(run.trace[i].point, choice)) break;
      replayer.insert(run.trace[i].point, choice);
      for (std::size_t j = i + 1; j < i + 3 && j < run.trace.size(); ++j) {
        if (!replayer.match(run.trace[j].point, choice)) break;
        replayer.insert(run.trace[j].point, choice);
      }
    }
    EXPECT_GT(checked, 100u) << c.name;
  }
}

// The searches answer the same with the skip and without: two replays of the same
// trace, one skipping far configurations, asked the same points at every step.
TEST(FarTerminals, TheSearchesAnswerTheSameWithoutTheSkip) {
  struct Reset {
    ~Reset() { Replayer::skip_far_terminals = true; }
  } reset;
  std::int64_t skipped = 0;
  for (const Case& c : cases()) {
    const RefineResult run = traced_run(c);
    Replayer skipping(c.pslg, rules_of(c)), building(c.pslg, rules_of(c));
    std::size_t replayed = 0;
    for (std::size_t i = 0; i < run.trace.size(); ++i) {
      if (i % 4 == 0)
        for (const Point& p : probes(run.trace, i, c.pslg)) {
          const std::string where = c.name + ", step " + std::to_string(i + 1) + ", (" + std::to_string(p.x) + ", " +
                                    std::to_string(p.y) + ")";
          Replayer::skip_far_terminals = true;
          const DeviationMatch a = skipping.diagnose(p);
          Replayer::skip_far_terminals = false;
          const DeviationMatch b = building.diagnose(p);
          EXPECT_EQ(a.deviation, b.deviation) << where;
          EXPECT_EQ(a.what, b.what) << where;
          expect_same(a.where, b.where, where);
          ASSERT_EQ(a.paper.size(), b.paper.size()) << where;
          for (std::size_t k = 0; k < a.paper.size(); ++k) expect_same(a.paper[k], b.paper[k], where);
          if (p.x == run.trace[i].point.x && p.y == run.trace[i].point.y) continue;  // matched below
          ReplayChoice ca, cb;
          Replayer::skip_far_terminals = true;
          const bool ma = skipping.match(p, ca);
          Replayer::skip_far_terminals = false;
          const bool mb = building.match(p, cb);
          ASSERT_EQ(ma, mb) << where;
          if (ma) expect_same(ca, cb, where);
        }
      const Point& p = run.trace[i].point;
      ReplayChoice ca, cb;
      Replayer::skip_far_terminals = true;
      const bool ma = skipping.match(p, ca);
      Replayer::skip_far_terminals = false;
      const bool mb = building.match(p, cb);
      ASSERT_EQ(ma, mb) << c.name << ", step " << i + 1;
      if (!ma) break;
      expect_same(ca, cb, c.name + ", step " + std::to_string(i + 1));
      skipping.insert(p, ca);
      building.insert(p, cb);
      ++replayed;
    }
    EXPECT_EQ(replayed, run.trace.size()) << c.name << ": the trace is replayed to its end";
    EXPECT_EQ(building.skipped_terminals_, 0) << c.name;
    skipped += skipping.skipped_terminals_;
  }
  // The skip is taken (else this test would compare a search with itself).
  EXPECT_GT(skipped, 1000);
}

// A sliver of height 1e-7 under an edge of length 1, bad at 20 degrees, whose
// circumcenter lies 1.25e6 below it. At a point near that circumcenter two rules
// are near (circumcenter, off-center: the triangle's own points, considered first)
// and the list has room for a third: the sliver's terminal configuration, 1.25e6
// away, though many more of its tolerances away than the off-center's. It is not
// skipped; the relaxed pass's is (the list is full by then).
TEST(FarTerminals, AListWithRoomForAThirdRuleStillTakesIt) {
  Pslg raw;
  raw.vertices = {{0, 0}, {1, 0}, {0.5, 1e-7}};
  raw.segments = {{0, 1, 0}, {1, 2, 0}, {2, 0, 0}};
  std::vector<std::string> warnings;
  const Pslg pslg = validate(raw, warnings);
  ReplayRules rules;
  rules.min_angle_deg = 20;
  const Replayer replayer(pslg, rules);
  const Point p{1.5, -1249999.99999995};  // the circumcenter is (0.5, -1249999.99999995)
  const DeviationMatch m = replayer.diagnose(p);
  EXPECT_EQ(m.deviation, Deviation::Unknown) << m.what;
  EXPECT_NE(m.what.find("circumcenter"), std::string::npos) << m.what;
  EXPECT_NE(m.what.find("off-center"), std::string::npos) << m.what;
  EXPECT_EQ(std::count(m.what.begin(), m.what.end(), '('), 3) << "three rules listed: " << m.what;
  EXPECT_GT(replayer.skipped_terminals_, 0);
}

}  // namespace
}  // namespace lepp::audit::replay_detail
