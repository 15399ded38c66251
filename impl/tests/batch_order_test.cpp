// SPDX-License-Identifier: GPL-3.0-or-later
// The batch order (docs/ALGORITHM.md section 7, "batch"): rounds of bad triangles
// whose regions are apart. What the definition promises: the members of a round
// do not depend on one another (reversed within each round, every step is still a
// step of the paper and the mesh is the same), their Lepps share no triangle, and
// both engines make the same rounds (the differential tests of order_test.cpp
// compare every order, batch included, trace and round by round).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "lepp/fast.h"
#include "lepp/io.h"
#include "lepp/reference.h"
#include "lepp/audit/replay.h"
#include "lepp/validate.h"
#include "random_pslg.h"
#include "result_diff.h"

namespace lepp {
namespace {

Pslg load(const std::string& name) {
  std::vector<std::string> warnings;
  return validate(read_poly(std::string(LEPP_SOURCE_DIR) + "/corpus/paper/" + name + ".poly"), warnings);
}

RefineOptions batch(double theta) {
  RefineOptions o;
  o.order = QueueOrder::Batch;
  o.min_angle_deg = theta;
  o.trace = true;
  return o;
}

// The mesh's triangles by their corners' coordinates (vertex ids depend on the
// insertion order, the triangles do not).
std::set<std::array<std::pair<double, double>, 3>> triangles(const Mesh& m) {
  std::set<std::array<std::pair<double, double>, 3>> out;
  for (const auto& t : m.triangles) {
    std::array<std::pair<double, double>, 3> c;
    for (int k = 0; k < 3; ++k) {
      const Point& p = m.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])];
      c[static_cast<std::size_t>(k)] = {p.x, p.y};
    }
    std::sort(c.begin(), c.end());
    out.insert(c);
  }
  return out;
}

// The trace's steps by round (1, 2, ...), in trace order.
std::map<std::int64_t, std::vector<const TraceStep*>> by_round(const RefineResult& r) {
  std::map<std::int64_t, std::vector<const TraceStep*>> rounds;
  for (const TraceStep& s : r.trace) rounds[s.round].push_back(&s);
  return rounds;
}

TEST(BatchOrder, RoundsAreNumberedFromOneAndCounted) {
  const RefineResult r = fast::refine(load("circles240"), batch(30));
  ASSERT_EQ(r.outcome, Outcome::Converged);
  ASSERT_FALSE(r.trace.empty());
  EXPECT_EQ(r.trace.front().round, 1);
  for (std::size_t k = 1; k < r.trace.size(); ++k) EXPECT_LE(r.trace[k - 1].round, r.trace[k].round) << k;
  EXPECT_EQ(r.trace.back().round, r.rounds);
  // Rounds are what the order is for: many insertions each, far fewer rounds than points.
  EXPECT_LT(r.rounds * 4, r.steiner_points);
  // The other orders have no rounds.
  RefineOptions fifo = batch(30);
  fifo.order = QueueOrder::Fifo;
  const RefineResult f = fast::refine(load("circles240"), fifo);
  EXPECT_EQ(f.rounds, 0);
  for (const TraceStep& s : f.trace) ASSERT_EQ(s.round, 0);
}

// No triangle of one member's Lepp is in another's, nor made by an earlier member
// of the same round (a triangle with one of its new points as a corner).
TEST(BatchOrder, MembersOfARoundShareNoLeppTriangle) {
  for (const char* name : {"A", "circles240", "rect162", "square400"}) {
    const Pslg p = load(name);
    const RefineResult r = fast::refine(p, batch(30));
    const auto n = static_cast<int>(p.vertices.size());
    int index = 0;
    std::map<const TraceStep*, int> vertex_of;
    for (const TraceStep& s : r.trace) vertex_of[&s] = n + index++;
    for (const auto& [round, steps] : by_round(r)) {
      std::set<Tri> seen;
      std::set<int> new_points;
      for (const TraceStep* s : steps) {
        for (Tri t : s->lepp) {
          for (int v : t) EXPECT_FALSE(new_points.count(v)) << name << " round " << round << ": a Lepp through a new triangle";
          std::sort(t.begin(), t.end());
          EXPECT_TRUE(seen.insert(t).second) << name << " round " << round << ": two members share a Lepp triangle";
        }
        new_points.insert(vertex_of[s]);
      }
    }
  }
}

// On the circle counts as inside (ALGORITHM.md section 7): a cavity's flood goes
// on through a triangle whose circumcircle passes exactly through the point. Grid
// problems by the midpoint method meet such ties (Square400 at 25 to 33 degrees,
// Rectangle162 at 30 and 33); both engines must make the same rounds there.
TEST(BatchOrder, BothEnginesMakeTheSameRoundsWhereThePointIsOnACircle) {
  for (const auto& [name, theta] : std::vector<std::pair<const char*, double>>{
           {"square400", 25}, {"square400", 28}, {"square400", 30}, {"square400", 33}, {"rect162", 30}, {"rect162", 33}}) {
    RefineOptions o = batch(theta);
    o.method = Method::Midpoint;
    o.max_steiner = 4000;
    const RefineResult f = fast::refine(load(name), o), r = reference::refine(load(name), o);
    EXPECT_EQ(impl_test::trace_difference(f.trace, r.trace), "") << name << " " << theta;
    EXPECT_EQ(f.rounds, r.rounds) << name << " " << theta;
  }
}

// The promise that lets a round run on many cores: its insertions commute. Each
// round's points, inserted in reverse order by the audit's replay, are each still
// a choice of the paper at that moment, and the mesh is the same. "" or what fails.
std::string rounds_commute(const Pslg& p, double theta, Method method, double max_area = 0) {
  RefineOptions o = batch(theta);
  o.method = method;
  o.max_area = max_area;
  o.max_steiner = 3000;
  const RefineResult r = fast::refine(p, o);
  audit::ReplayRules rules;
  rules.method = method;
  rules.min_angle_deg = theta;
  rules.max_area = max_area;
  audit::Replay replay(p, rules);
  std::size_t step = 0;
  for (const auto& [round, steps] : by_round(r)) {
    for (auto it = steps.rbegin(); it != steps.rend(); ++it, ++step) {
      audit::ReplayChoice choice;
      if (!replay.match((*it)->point, choice))
        return fmt::format("round {}, reversed: step {} ({:.17g}, {:.17g}) is no choice of the paper", round, step,
                           (*it)->point.x, (*it)->point.y);
      replay.insert((*it)->point, choice);
    }
  }
  if (triangles(replay.mesh()) != triangles(r.mesh)) return "the rounds reversed make another mesh";
  return "";
}

TEST(BatchOrder, ARoundsInsertionsCommuteOnThePapersProblems) {
  for (const char* name : {"A", "circles240", "rect162"})
    for (Method method : {Method::Centroid, Method::Midpoint})
      EXPECT_EQ(rounds_commute(load(name), method == Method::Centroid ? 30 : 20, method), "")
          << name << " " << to_string(method);
  EXPECT_EQ(rounds_commute(load("A"), 25, Method::Centroid, 0.5), "") << "A with a size bound";
}

RC_GTEST_PROP(BatchOrder, ARoundsInsertionsCommuteOnGeneratedInputs, ()) {
  const Pslg p = impl_test::to_pslg(*impl_test::gen_raw_pslg(16, 16));
  RC_PRE(!p.vertices.empty());
  const double theta = *rc::gen::inRange(15, 31);
  const Method method = *rc::gen::element(Method::Centroid, Method::Midpoint);
  const double max_area = *rc::gen::inRange(0, 3) == 0 ? 4.0 / *rc::gen::inRange(20, 400) : 0.0;
  RC_ASSERT(rounds_commute(p, theta, method, max_area) == "");
}

}  // namespace
}  // namespace lepp
