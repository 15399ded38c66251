// SPDX-License-Identifier: GPL-3.0-or-later
// The search around a point leaves out the far bounding box's corners
// (Replayer::domain_faces_around): white-box, no face around a corner is in the
// domain at any step of the traces, the search's faces are the same with the
// skip and without (each face, in order), and so are the searches' answers; on
// a square whose sides carry many Steiner points, a point on a boundary edge no
// longer turns the corner's fan.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "trace_cases.h"

namespace lepp::audit::replay_detail {
namespace {

using namespace trace_cases;

struct Restore {
  ~Restore() { Replayer::skip_box_corners = true; }
};

std::vector<VH> box_corners(const Triangulation& tr) {
  std::vector<VH> out;
  for (VH v : tr.cdt.finite_vertex_handles())
    if (id(v) < 0) out.push_back(v);
  return out;
}

// faces_near with the skip and without, on the same replayer: the same faces in
// the same order. Returns the faces the skip did not turn.
std::int64_t expect_same_faces(Replayer& r, const Point& p, bool wide, const std::string& where) {
  Restore restore;
  bool at_a = false, at_b = false;
  Replayer::skip_box_corners = true;
  const std::int64_t before = r.star_faces_walked_;
  const std::vector<FH> a = r.faces_near(p, at_a, wide);
  const std::int64_t with = r.star_faces_walked_ - before;
  Replayer::skip_box_corners = false;
  const std::vector<FH> b = r.faces_near(p, at_b, wide);
  const std::int64_t without = r.star_faces_walked_ - before - with;
  EXPECT_EQ(at_a, at_b) << where;
  EXPECT_TRUE(a == b) << where << ": " << a.size() << " faces with the skip, " << b.size() << " without";
  return without - with;
}

TEST(BoxCorners, NoFaceAroundACornerIsEverInTheDomain) {
  std::size_t checked = 0;
  for (const Case& c : cases()) {
    const RefineResult run = traced_run(c);
    Replayer replayer(c.pslg, rules_of(c));
    const std::vector<VH> corners = box_corners(replayer.tr);
    ASSERT_EQ(corners.size(), 4u) << c.name;
    for (std::size_t i = 0; i <= run.trace.size(); ++i) {
      for (VH v : corners) {
        Cdt::Face_circulator fc = replayer.tr.cdt.incident_faces(v), done = fc;
        do {
          EXPECT_FALSE(in_domain(replayer.tr, fc)) << c.name << ", step " << i;
          ++checked;
        } while (++fc != done);
      }
      if (i == run.trace.size()) break;
      ReplayChoice choice;
      ASSERT_TRUE(replayer.match(run.trace[i].point, choice)) << c.name << ", step " << i + 1;
      replayer.insert(run.trace[i].point, choice);
    }
  }
  EXPECT_GT(checked, 1000u);
}

// At every step, the probes of trace_cases.h and every boundary edge's midpoint
// (on the edge: located in the domain face or the outside one), one ring and two.
TEST(BoxCorners, TheSearchFindsTheSameFacesWithoutTheSkip) {
  std::int64_t saved = 0;
  for (const Case& c : cases()) {
    const RefineResult run = traced_run(c);
    Replayer replayer(c.pslg, rules_of(c));
    for (std::size_t i = 0; i < run.trace.size(); ++i) {
      const std::string where = c.name + ", step " + std::to_string(i + 1);
      std::vector<Point> points = probes(run.trace, i, c.pslg);
      for (FH f : replayer.tr.cdt.finite_face_handles())
        for (int e = 0; e < 3; ++e)
          if (in_domain(replayer.tr, f) && f->is_constrained(e) && !in_domain(replayer.tr, f->neighbor(e))) {
            const Point a = replayer.tr.coords[static_cast<std::size_t>(id(f->vertex(Cdt::ccw(e))))];
            const Point b = replayer.tr.coords[static_cast<std::size_t>(id(f->vertex(Cdt::cw(e))))];
            points.push_back({(a.x + b.x) / 2, (a.y + b.y) / 2});
          }
      for (const Point& p : points)
        for (const bool wide : {false, true}) saved += expect_same_faces(replayer, p, wide, where);
      ReplayChoice choice;
      ASSERT_TRUE(replayer.match(run.trace[i].point, choice)) << where;
      replayer.insert(run.trace[i].point, choice);
    }
  }
  EXPECT_GT(saved, 0) << "some point's search had a corner among its vertices";
}

TEST(BoxCorners, TheSearchesAnswerTheSameWithoutTheSkip) {
  Restore restore;
  for (const Case& c : cases()) {
    const RefineResult run = traced_run(c);
    Replayer skipping(c.pslg, rules_of(c)), turning(c.pslg, rules_of(c));
    const std::size_t replayed =
        replay_both(c, run, skipping, turning, [](bool first) { Replayer::skip_box_corners = first; });
    EXPECT_EQ(replayed, run.trace.size()) << c.name << ": the trace is replayed to its end";
  }
}

// The unit square refined to a small area bound: every side carries tens of
// Steiner points, each joined to a corner of the box outside it. The midpoint of
// a side's edge has that corner among its search's vertices: without the skip
// the search turns the corner's whole fan.
TEST(BoxCorners, APointOnASideDoesNotTurnTheCornersFan) {
  Pslg raw;
  raw.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  raw.segments = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}, {3, 0, 0}};
  std::vector<std::string> warnings;
  const Pslg pslg = validate(raw, warnings);
  RefineOptions options;
  options.min_angle_deg = 30;
  options.max_area = 2e-4;
  options.trace = true;
  const RefineResult run = fast::refine(pslg, options);
  ReplayRules rules;
  rules.min_angle_deg = 30;
  rules.max_area = options.max_area;
  Replayer replayer(pslg, rules);
  for (const TraceStep& step : run.trace) {
    ReplayChoice choice;
    ASSERT_TRUE(replayer.match(step.point, choice));
    replayer.insert(step.point, choice);
  }
  auto degree = [&](VH v) {
    std::int64_t n = 0;
    Cdt::Face_circulator fc = replayer.tr.cdt.incident_faces(v), done = fc;
    do ++n;
    while (++fc != done);
    return n;
  };
  std::int64_t fan = 0;
  for (VH v : box_corners(replayer.tr)) fan = std::max(fan, degree(v));
  ASSERT_GT(fan, 40) << "a corner joined to many Steiner points of the sides";
  // Each side's edge: the outside triangle across it has a corner for its apex
  // (the domain is convex), the one corner among the search's four vertices;
  // the skip leaves out exactly that corner's faces.
  std::size_t edges = 0;
  for (FH f : replayer.tr.cdt.finite_face_handles())
    for (int e = 0; e < 3; ++e)
      if (in_domain(replayer.tr, f) && f->is_constrained(e)) {
        const Point a = replayer.tr.coords[static_cast<std::size_t>(id(f->vertex(Cdt::ccw(e))))];
        const Point b = replayer.tr.coords[static_cast<std::size_t>(id(f->vertex(Cdt::cw(e))))];
        const FH out = f->neighbor(e);
        const VH apex = out->vertex(out->index(f));
        ASSERT_LT(id(apex), 0) << "the apex across a side is a corner";
        EXPECT_EQ(expect_same_faces(replayer, {(a.x + b.x) / 2, (a.y + b.y) / 2}, false, "a side's edge"), degree(apex));
        ++edges;
      }
  EXPECT_GT(edges, 4 * 20u) << "tens of Steiner points on every side";
}

}  // namespace
}  // namespace lepp::audit::replay_detail
