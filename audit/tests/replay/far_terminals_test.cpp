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

#include "trace_cases.h"

namespace lepp::audit::replay_detail {
namespace {

using namespace trace_cases;

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

// The search around a point leaves out the other reading's area centroid where
// area_centroid_beyond says it is surely beyond its tolerance: at every terminal pair of
// the meshes, at points a few ulps to many tolerances off the exact area centroid, the
// replay's own distance to it (each difference through to_double) is then beyond the
// tolerance too; and where the point is within the tolerance it is never left out.
TEST(FarTerminals, TheAreaCentroidIsLeftOutOnlyBeyondItsTolerance) {
  std::size_t beyond = 0, kept = 0;
  for (const Case& c : cases()) {
    if (c.area) continue;  // the vertex reading: the catalogue's other reading is the area's
    const RefineResult run = traced_run(c);
    Replayer replayer(c.pslg, rules_of(c));
    for (std::size_t i = 0; i <= run.trace.size(); i += 5) {
      for (FH f : replayer.tr.cdt.finite_face_handles()) {
        if (!in_domain(replayer.tr, f)) continue;
        for (int l = 0; l < 3; ++l) {
          FH n = f->neighbor(l);
          if (f->is_constrained(l) || replayer.tr.cdt.is_infinite(n) || !in_domain(replayer.tr, n)) continue;
          const std::optional<Candidate> g = quad_centroid(Rule::QuadCentroid, f, n, l, CentroidReading::Area);
          if (!g) continue;
          const double tol = point_tolerance(replayer.rules, g->scale);
          const Point at = rounded_point(*g);
          std::vector<Point> asked = {at, {ulps(at.x, 2), at.y}, {at.x, ulps(at.y, -7)}};
          for (const double r : {0.5, 0.999, 1.001, 1.5, 4.0, 1e3}) {
            asked.push_back({at.x + r * tol, at.y});
            asked.push_back({at.x, at.y - r * tol});
          }
          VH a = f->vertex(Cdt::ccw(l)), b = f->vertex(Cdt::cw(l)), cv = f->vertex(l), d = n->vertex(n->index(f));
          for (const Point& p : asked) {
            const double dist = std::max(std::abs(CGAL::to_double(FT(p.x) - g->point.x())),
                                         std::abs(CGAL::to_double(FT(p.y) - g->point.y())));
            if (area_centroid_beyond(replayer.rules, p, a, b, cv, d)) {
              ASSERT_GT(dist, tol) << c.name << ": (" << p.x << ", " << p.y << ")";
              ++beyond;
            } else {
              ++kept;
            }
          }
        }
      }
      if (i == run.trace.size()) break;
      for (std::size_t j = i; j < i + 5 && j < run.trace.size(); ++j) {
        ReplayChoice choice;
        ASSERT_TRUE(replayer.match(run.trace[j].point, choice)) << c.name;
        replayer.insert(run.trace[j].point, choice);
      }
    }
  }
  // Both answers are given (else the filter is never taken, or takes everything).
  EXPECT_GT(beyond, 1000u);
  EXPECT_GT(kept, 1000u);
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
    const std::size_t replayed =
        replay_both(c, run, skipping, building, [](bool first) { Replayer::skip_far_terminals = first; });
    EXPECT_EQ(replayed, run.trace.size()) << c.name << ": the trace is replayed to its end";
    EXPECT_EQ(building.skipped_terminals_, 0) << c.name;
    // The same searches found them: a point the search around it missed with the skip
    // would still be found by the last search, over the whole mesh.
    EXPECT_EQ(skipping.searched_everywhere_, building.searched_everywhere_) << c.name;
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
