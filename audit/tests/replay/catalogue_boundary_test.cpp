// SPDX-License-Identifier: GPL-3.0-or-later
// The deviation catalogue (Replay::diagnose) at its boundaries (issue 30, item
// 7): every rule that has a point in each terminal triangle is asked in t2 as
// well as in t1, and the `precision` band ends at 1000 times the point
// tolerance. Each test names the mutants of tools/mutation/mutants.txt it kills.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "lepp/io.h"
#include "lepp/audit/replay.h"
#include "lepp/validate.h"

namespace lepp {
namespace {

using audit::Replay;
using audit::ReplayChoice;
using audit::ReplayRules;
using audit::to_string;

Pslg paper_input(const std::string& name) {
  std::vector<std::string> warnings;
  return validate(read_poly(std::string(LEPP_SOURCE_DIR) + "/corpus/paper/" + name), warnings);
}

ReplayRules rules_at(double theta) {
  ReplayRules r;
  r.min_angle_deg = theta;
  return r;
}

// Every paper choice of the current mesh (all_choices has them nearest to p first).
std::vector<ReplayChoice> every_choice(Replay& replay) {
  std::size_t total = 0;
  replay.all_choices({0, 0}, 1, total);
  return replay.all_choices({0, 0}, total, total);
}

bool same_triangle(Tri a, Tri b) {
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  return a == b;
}

// The vertex of t that is not on edge e.
int apex(const Tri& t, const std::array<int, 2>& e) {
  for (int v : t)
    if (v != e[0] && v != e[1]) return v;
  return -1;
}

// The replay advanced by its own first choice, `steps` times: meshes part way through a refinement.
void advance(Replay& replay, std::size_t steps) {
  for (std::size_t i = 0; i < steps; ++i) {
    const std::vector<ReplayChoice> all = every_choice(replay);
    if (all.empty()) return;
    ReplayChoice c;
    ASSERT_TRUE(replay.match(all.front().point, c));
    replay.insert(all.front().point, c);
  }
}

// A terminal pair seen only one way round (no choice has t2 as its t1 over the
// same edge): a rule asked for t1 alone would miss t2's points here. Where a
// program takes t2's triangle centroid, or the midpoint of one of t2's other
// edges, the catalogue must still name it.
// Kills ref-diagnose-t2-triangle-centroid-skipped and ref-diagnose-t2-other-edges-skipped.
TEST(CatalogueBoundary, RulesOfTheSecondTerminalTriangleAreAsked) {
  std::size_t pairs = 0, centroids = 0, midpoints = 0;
  for (const char* name : {"A.poly", "rect162.poly"}) {
    Replay replay(paper_input(name), rules_at(30));
    for (std::size_t round = 0; round < 6; ++round) {
      const Mesh mesh = replay.mesh();
      const std::vector<ReplayChoice> all = every_choice(replay);
      for (const ReplayChoice& c : all) {
        if (c.t2[0] < 0) continue;  // a constrained terminal edge: no t2
        const bool both_ways = std::any_of(all.begin(), all.end(), [&](const ReplayChoice& o) {
          return o.t2[0] >= 0 && same_triangle(o.t1, c.t2);
        });
        if (both_ways) continue;
        ++pairs;
        const std::array<int, 2>& e = c.terminal_edge;
        const Point& a = mesh.vertices[e[0]];
        const Point& b = mesh.vertices[e[1]];
        const Point& d = mesh.vertices[apex(c.t2, e)];
        // t2's triangle centroid, as a program computes it in doubles.
        const Point g{(a.x + b.x + d.x) / 3, (a.y + b.y + d.y) / 3};
        ReplayChoice unused;
        if (!replay.match(g, unused)) {
          ++centroids;
          EXPECT_STREQ(to_string(replay.diagnose(g).deviation), "triangle-centroid")
              << name << ": t2's centroid (" << g.x << ", " << g.y << ")";
        }
        // The midpoints of t2's two other edges: some catalogue rule (another
        // edge's midpoint, or Remark 10 reversed where it is the star's edge).
        for (const Point* u : {&a, &b}) {
          const Point m{(u->x + d.x) / 2, (u->y + d.y) / 2};
          if (replay.match(m, unused)) continue;
          ++midpoints;
          EXPECT_STRNE(to_string(replay.diagnose(m).deviation), "unknown") << name << ": t2's edge midpoint (" << m.x << ", " << m.y << ")";
        }
      }
      advance(replay, 5);
    }
  }
  // The inputs must give the case this test is about.
  EXPECT_GT(pairs, 0u);
  EXPECT_GT(centroids, 0u);
  EXPECT_GT(midpoints, 0u);
}

// A point moved off a paper choice by just under, then just over, 1000 times
// the choice's point tolerance: `precision` inside the band, not outside it.
// Kills ref-diagnose-precision-band-narrow and ref-diagnose-precision-band-wide.
TEST(CatalogueBoundary, PrecisionBandEndsAtAThousandTolerances) {
  std::size_t checked = 0;
  for (const char* name : {"A.poly", "circles240.poly"}) {
    Replay replay(paper_input(name), rules_at(25));
    advance(replay, 3);
    const std::vector<ReplayChoice> all = every_choice(replay);
    ASSERT_FALSE(all.empty()) << name;
    const ReplayChoice& c = all.front();
    ASSERT_GT(c.tolerance, 0) << name;
    // Only where no other choice is near: the band must be this choice's.
    double nearest_other = INFINITY;
    for (const ReplayChoice& o : all)
      if (o.point.x != c.point.x || o.point.y != c.point.y)
        nearest_other = std::min(nearest_other, std::max(std::abs(o.point.x - c.point.x), std::abs(o.point.y - c.point.y)));
    if (nearest_other < 3000 * c.tolerance) continue;
    ++checked;
    for (int sign : {1, -1}) {
      const Point inside{c.point.x + sign * 990 * c.tolerance, c.point.y};
      const Point outside{c.point.x + sign * 1010 * c.tolerance, c.point.y};
      ReplayChoice unused;
      ASSERT_FALSE(replay.match(inside, unused)) << name << ": 990 tolerances away is no choice";
      const audit::DeviationMatch in = replay.diagnose(inside);
      EXPECT_STREQ(to_string(in.deviation), "precision") << name << " sign " << sign << ": " << in.what;
      EXPECT_STRNE(to_string(replay.diagnose(outside).deviation), "precision") << name << " sign " << sign;
    }
  }
  EXPECT_GT(checked, 0u);
}

}  // namespace
}  // namespace lepp
