// SPDX-License-Identifier: GPL-3.0-or-later
// The replay's search one ring of triangles wider (docs/CONFORMANCE.md, "A
// midpoint past a sliver"), white-box (audit/src/replay/replayer.h): lepp's own
// trace of fuzz_engine's finding replayed, no step's choice left to the last,
// whole-mesh search (match_everywhere, slow), which finds the same choice and so
// hid the wider search's removal from every other test. Kills
// replay-no-wider-search (tools/mutation/mutants.txt).
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "../../src/replay/replayer.h"
#include "lepp/fast.h"
#include "lepp/io.h"
#include "lepp/validate.h"

namespace lepp::audit::replay_detail {
namespace {

Pslg past_sliver() {
  std::vector<std::string> warnings;
  return validate(read_poly(LEPP_SOURCE_DIR "/corpus/regressions/precision/midpoint-past-sliver.poly"), warnings);
}

// The ids of the vertices the first search around p starts from (faces_near
// without `wide`): those of the face holding p, and the vertex across the edge
// p lies on. That search looks only at the faces around them, so a choice whose
// terminal pair shares none of them is one it missed: had it found any choice,
// match() would have returned that one.
std::set<int> vertices_around(const Triangulation& tr, const Point& p) {
  Cdt::Locate_type lt;
  int li;
  FH f = tr.cdt.locate(CPoint(p.x, p.y), lt, li);
  std::set<int> out;
  for (int i = 0; i < 3; ++i)
    if (!tr.cdt.is_infinite(f->vertex(i))) out.insert(id(f->vertex(i)));
  if (lt == Cdt::EDGE) {
    FH n = f->neighbor(li);
    if (!tr.cdt.is_infinite(n->vertex(n->index(f)))) out.insert(id(n->vertex(n->index(f))));
  }
  return out;
}

bool shares_a_vertex(const std::set<int>& around, const Tri& t) {
  return std::any_of(t.begin(), t.end(), [&](int v) { return v >= 0 && around.count(v); });
}

// fuzz_engine's finding (centroid, 13.9 degrees, fifo): a constrained edge's
// midpoint rounded half an ulp beyond the edge lies past a sliver, in a triangle
// that shares no vertex with the terminal pair (step 357 of 405 today). The
// search one ring wider finds that pair; without it only match_everywhere did
// (searched_everywhere_), and lepp's trace still conformed.
TEST(ReplayWiderSearch, MidpointPastASliverIsFoundOneRingWider) {
  const Pslg pslg = past_sliver();
  RefineOptions options;
  options.method = Method::Centroid;
  options.min_angle_deg = 13.9;
  options.order = QueueOrder::Fifo;
  options.trace = true;
  const RefineResult result = fast::refine(pslg, options);
  ASSERT_FALSE(result.trace.empty());

  ReplayRules rules;
  rules.method = Method::Centroid;
  rules.min_angle_deg = 13.9;
  Replayer replayer(pslg, rules);
  std::vector<std::size_t> past_sliver_steps;  // 1-based: steps whose choice the first search missed
  for (std::size_t i = 0; i < result.trace.size(); ++i) {
    const Point& p = result.trace[i].point;
    const std::set<int> around = vertices_around(replayer.tr, p);
    ReplayChoice choice;
    ASSERT_TRUE(replayer.match(p, choice)) << "step " << i + 1 << " of " << result.trace.size() << " is no choice";
    ASSERT_EQ(replayer.searched_everywhere_, 0)
        << "step " << i + 1 << ": only the whole-mesh search found its choice (the searches around the point, "
        << "one ring wider too, missed it)";
    if (!shares_a_vertex(around, choice.t1) && !shares_a_vertex(around, choice.t2)) past_sliver_steps.push_back(i + 1);
    replayer.insert(p, choice);
  }
  // The input still has a step the wider search is for: the first search misses its choice.
  EXPECT_FALSE(past_sliver_steps.empty()) << "no step's terminal pair lies past the vertices around its point";
}

}  // namespace
}  // namespace lepp::audit::replay_detail
