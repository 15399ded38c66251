// SPDX-License-Identifier: GPL-3.0-or-later
// Remark 10's test of a centroid of vertices against a triangle (inside_status,
// audit/src/replay/choice_points.h) from the mean's doubles: the same answer as the
// lazy-exact test of the point, for every face of the traces' meshes (at the origin,
// far from it, at subnormal scale) and means of two to four of their vertices: on
// the faces' sides (midpoints), their centroids, quads' centroids, and means whose
// points were moved a few ulps, under tolerances from none to far beyond a side.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "trace_cases.h"

namespace lepp::audit::replay_detail {
namespace {

using namespace trace_cases;

Candidate mean_candidate(const std::vector<Point>& pts) {
  Candidate g;
  FT sx = 0, sy = 0;
  for (const Point& p : pts) {
    g.mean.x[static_cast<std::size_t>(g.mean.n)] = p.x, g.mean.y[static_cast<std::size_t>(g.mean.n)] = p.y, ++g.mean.n;
    sx += FT(p.x), sy += FT(p.y);
  }
  g.point = CPoint(sx / g.mean.n, sy / g.mean.n);
  return g;
}

Point at(VH v) { return *doubles_of(v->point()); }

TEST(InsideMean, TheSameAnswerAsTheExactPoint) {
  std::map<int, int> answers;  // inside_status's answer -> how often
  std::size_t asked = 0;
  for (const Case& c : cases()) {
    const RefineResult run = traced_run(c);
    Replayer replayer(c.pslg, rules_of(c));
    for (std::size_t i = 0; i < run.trace.size(); ++i) {
      ReplayChoice choice;
      ASSERT_TRUE(replayer.match(run.trace[i].point, choice)) << c.name;
      replayer.insert(run.trace[i].point, choice);
    }
    for (FH f : replayer.tr.cdt.finite_face_handles()) {
      if (!in_domain(replayer.tr, f)) continue;
      const Point a = at(f->vertex(0)), b = at(f->vertex(1)), d = at(f->vertex(2));
      const FH n = f->neighbor(0);
      const double scale = std::max({std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y), std::abs(d.x), std::abs(d.y)});
      std::vector<std::vector<Point>> means = {
          {a, b}, {b, d}, {d, a}, {a, b, d},  // on each side; the centroid
          {{ulps(a.x, 3), a.y}, b},  {a, {b.x, ulps(b.y, 5)}},  // a side's midpoint moved by ulps
          {{ulps(a.x, 40), ulps(a.y, 40)}, {ulps(b.x, 40), ulps(b.y, 40)}}};
      if (!replayer.tr.cdt.is_infinite(n)) means.push_back({a, b, d, at(n->vertex(n->index(f)))});  // a quad's centroid
      for (const std::vector<Point>& m : means) {
        const Candidate g = mean_candidate(m);
        for (const double tol : {0.0, point_tolerance(ReplayRules{}, scale), 1e-9 * scale, 0.3 * scale}) {
          const int fast = inside_status(f, g, tol), exact = inside_status(f, g.point, tol);
          EXPECT_EQ(fast, exact) << c.name << ", tolerance " << tol;
          ++answers[exact];
          ++asked;
        }
      }
    }
  }
  EXPECT_GT(asked, 10000u);
  for (const int answer : {-1, 0, 1}) EXPECT_GT(answers[answer], 100) << "inside_status " << answer;
}

// Points not of doubles take the lazy test: a mean of none is the point's own test.
TEST(InsideMean, APointWithNoMeanIsTestedAsItIs) {
  Pslg raw;
  raw.vertices = {{0, 0}, {4, 0}, {0, 3}};
  raw.segments = {{0, 1, 0}, {1, 2, 0}, {2, 0, 0}};
  std::vector<std::string> warnings;
  Replayer replayer(validate(raw, warnings), ReplayRules{});
  for (FH f : replayer.tr.cdt.finite_face_handles()) {
    if (!in_domain(replayer.tr, f)) continue;
    Candidate g;
    g.point = CPoint(FT(1) / 3, FT(1) / 7);  // no double: no mean
    EXPECT_EQ(inside_status(f, g, 0), 1);
    g.point = CPoint(FT(2), FT(0));  // on a side
    EXPECT_EQ(inside_status(f, g, 0), 0);
  }
}

}  // namespace
}  // namespace lepp::audit::replay_detail
