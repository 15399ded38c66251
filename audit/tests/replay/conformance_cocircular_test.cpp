// SPDX-License-Identifier: GPL-3.0-or-later
// The replay and cocircular cells: every constrained Delaunay mesh of the
// points is followed (any triangulation of an exactly cocircular cell), the
// replay's mesh stays constrained Delaunay, and a point that is no choice
// under any triangulation is still rejected.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "conformance_test_support.h"
#include "lepp/audit/judge/conformance.h"
#include "lepp/certify.h"
#include "lepp/fast.h"
#include "lepp/gen.h"
#include "lepp/gen_degenerate.h"
#include "lepp/gen_lattice_box.h"
#include "lepp/gen_symmetry.h"
#include "lepp/reference.h"
#include "lepp/audit/replay.h"
#include "lepp/validate.h"

namespace lepp::audit {
namespace {

Pslg validated(Pslg p) {
  std::vector<std::string> warnings;
  return validate(p, warnings);
}

// The boundary of [0, w] x [0, h], every lattice point a vertex.
Pslg lattice_rectangle(int w, int h) { return validated(gen::lattice_box(w, h)); }

// A mesher run on the transformed input, its points mapped back.
std::vector<Point> trace_under(const Pslg& p, const gen::LatticeSymmetry& s, bool fast_engine, Method m, QueueOrder q,
                               double theta, std::int64_t max_steiner = 400) {
  const RefineOptions o = test::traced_options(m, q, theta, max_steiner);
  const Pslg moved = s.apply(p);
  RefineResult r = fast_engine ? fast::refine(moved, o) : reference::refine(moved, o);
  std::vector<Point> out;
  for (const TraceStep& st : r.trace) out.push_back(s.undo(st.point));
  return out;
}

ConformanceOptions options(Method m, double theta) {
  ConformanceOptions c;
  c.method = m;
  c.min_angle_deg = theta;
  return c;
}

// The known false rejection (docs/CONFORMANCE.md, before the fix): the
// boundary lattice points of a 4 x 3 rectangle. lepp's engine run on it
// turned by -90 degrees builds an initial CDT whose cocircular cells are
// triangulated otherwise than CGAL's CDT of the unturned rectangle (six
// diagonals differ), and its first point is a choice only there.
TEST(CocircularCells, EngineTraceUnderAQuarterTurnConforms) {
  const Pslg p = lattice_rectangle(4, 3);
  const gen::LatticeSymmetry minus90{3, false};
  for (bool fast_engine : {true, false}) {
    std::vector<Point> trace = trace_under(p, minus90, fast_engine, Method::Centroid, QueueOrder::Fifo, 30);
    ASSERT_FALSE(trace.empty());
    ConformanceReport r = check_conformance(p, trace, options(Method::Centroid, 30));
    EXPECT_TRUE(r.conforms) << (fast_engine ? "fast: " : "reference: ") << describe(r);
    EXPECT_GT(r.cocircular_ties, 0) << "the initial CDT's cocircular edges are counted";
    EXPECT_GT(r.cocircular_flips, 2) << "more than the one or two flips of the local search";
    // Without following other triangulations, the first point is no choice.
    ConformanceOptions rigid = options(Method::Centroid, 30);
    rigid.follow_cocircular_flips = false;
    ConformanceReport no = check_conformance(p, trace, rigid);
    ASSERT_FALSE(no.conforms);
    EXPECT_EQ(no.failure->step, 0u) << describe(no);
  }
}

// The older searches, kept as the fallback when the search of the cells runs
// out of its budget (0 here): one or two flips near the point, then CGAL's tie
// rule. On small lattice rectangles under the eight symmetries some step is
// followed by exactly one or two flips with no switch to CGAL's rule (its
// switch flips more). Traces that need the search stop where they need it.
TEST(CocircularCells, WithoutTheSearchOneOrTwoLocalFlipsStillFollowATrace) {
  std::size_t local_steps = 0, traces = 0;
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{2, 1}, {2, 2}, {3, 2}, {4, 3}})
    for (int turns = 0; turns < 4; ++turns)
      for (bool mirrored : {false, true}) {
        const Pslg p = lattice_rectangle(w, h);
        const std::vector<Point> trace =
            trace_under(p, gen::LatticeSymmetry{turns, mirrored}, true, Method::Centroid, QueueOrder::Fifo, 30);
        if (trace.empty()) continue;
        ++traces;
        audit::ReplayRules rules;
        rules.method = Method::Centroid;
        rules.min_angle_deg = 30;
        rules.angle_tolerance_deg = ConformanceOptions().angle_tolerance_deg;
        rules.cocircular_search_budget = 0;
        audit::Replay replay(p, rules);
        for (std::size_t i = 0; i < trace.size(); ++i) {
          audit::ReplayChoice choice;
          const std::int64_t before = replay.cocircular_flips();
          if (!replay.match(trace[i], choice)) break;  // needs the search (the 4 x 3 turned: step 0)
          const std::int64_t flips = replay.cocircular_flips() - before;
          if (flips == 1 || flips == 2) ++local_steps;
          replay.insert(trace[i], choice);
        }
      }
  EXPECT_GT(traces, 0u);
  EXPECT_GT(local_steps, 0u) << "no step was followed by the one-or-two-flip search";
}

// ---- every symmetry, both engines, both methods, both orders ----

TEST(LatticeSymmetry, EightDistinctMapsEachUndoneExactly) {
  const Point q{3, -1.25};
  std::set<std::pair<double, double>> images;
  for (int k = 0; k < 8; ++k) {
    const gen::LatticeSymmetry s{k % 4, k >= 4};
    const Point image = s.apply(q);
    images.insert({image.x, image.y});
    EXPECT_EQ(s.undo(image), q) << k;
    EXPECT_EQ(std::hypot(image.x, image.y), std::hypot(q.x, q.y)) << k;
  }
  EXPECT_EQ(images.size(), 8u);
  EXPECT_EQ((gen::LatticeSymmetry{3, false}.apply(Point{1, 0})), (Point{0, -1})) << "3 quarter turns: -90 degrees";
}

bool is_cdt(const Pslg& p, const Mesh& m, std::string& why) {
  certify::Report c = certify::certify(p, m);
  for (const certify::Violation& v : c.violations)
    if (certify::check_of(v.reason) != certify::Check::MinAngle && certify::check_of(v.reason) != certify::Check::Theorem2) {
      why = v.message;
      return false;
    }
  return true;
}

// Steps the trace through the replay; after every match that flipped
// cocircular edges, the replay's mesh must still be a constrained Delaunay
// triangulation of the same points (the certifier's topology, input,
// constraint and Delaunay checks). Returns the step that is no choice, or
// trace.size().
std::size_t replay_checking_the_mesh(const Pslg& p, const std::vector<Point>& trace, Method m, double theta,
                                     std::string& why) {
  audit::ReplayRules rules;
  rules.method = m;
  rules.min_angle_deg = theta;
  rules.angle_tolerance_deg = ConformanceOptions().angle_tolerance_deg;
  audit::Replay replay(p, rules);
  for (std::size_t i = 0; i < trace.size(); ++i) {
    const std::int64_t flips = replay.cocircular_flips();
    const std::size_t vertices = replay.mesh().vertices.size();
    audit::ReplayChoice choice;
    if (!replay.match(trace[i], choice)) return i;
    if (replay.cocircular_flips() != flips) {
      Mesh mesh = replay.mesh();
      if (mesh.vertices.size() != vertices || !is_cdt(p, mesh, why)) {
        why = "step " + std::to_string(i) + ": the flipped mesh is no CDT of the same points: " + why;
        return i;
      }
    }
    replay.insert(trace[i], choice);
  }
  return trace.size();
}

struct Input {
  const char* name;
  Pslg pslg;
};

// Lattice inputs with cocircular cells: rectangles' boundary points (cells
// of 4 to 8 points), a grid, the points of a lattice circle with its centre,
// and a lattice polygon.
std::vector<Input> lattice_inputs() {
  std::vector<Input> out{{"rect4x3", lattice_rectangle(4, 3)}, {"rect6x4", lattice_rectangle(6, 4)},
                         {"rect5x5", lattice_rectangle(5, 5)}};
  Pslg grid = lattice_rectangle(4, 3);
  for (int x = 1; x < 4; ++x)
    for (int y = 1; y < 3; ++y) grid.vertices.push_back({double(x), double(y)});
  out.push_back({"grid4x3", validated(grid)});
  Pslg circle;
  circle.vertices = {{-7, -7}, {7, -7}, {7, 7}, {-7, 7}};
  for (int i = 0; i < 4; ++i) circle.segments.push_back({i, (i + 1) % 4, 1});
  for (int x = -5; x <= 5; ++x)
    for (int y = -5; y <= 5; ++y)
      if (x * x + y * y == 25) circle.vertices.push_back({double(x), double(y)});
  circle.vertices.push_back({0, 0});
  out.push_back({"circle25", validated(circle)});
  Pslg polygon;
  for (Point q : {Point{0, 4}, {1, 2}, {2, 0}, {3, 0}, {4, 0}, {4, 1}, {4, 2}, {3, 3}, {2, 4}, {1, 4}}) polygon.vertices.push_back(q);
  for (int i = 0; i < 10; ++i) polygon.segments.push_back({i, (i + 1) % 10, 1});
  out.push_back({"polygon10", validated(polygon)});
  return out;
}

TEST(CocircularCells, EnginesConformUnderEveryLatticeSymmetry) {
  std::size_t runs = 0, flipped = 0;
  for (const Input& in : lattice_inputs())
    for (int k = 0; k < 8; ++k) {
      const gen::LatticeSymmetry s{k % 4, k >= 4};
      for (bool fast_engine : {true, false})
        for (Method m : {Method::Centroid, Method::Midpoint})
          for (QueueOrder q : {QueueOrder::Fifo, QueueOrder::Lifo}) {
            const double theta = m == Method::Centroid ? 30 : 25;
            std::vector<Point> trace = trace_under(in.pslg, s, fast_engine, m, q, theta, 300);
            std::string why;
            std::size_t step = replay_checking_the_mesh(in.pslg, trace, m, theta, why);
            std::string what = std::string(in.name) + " under " + std::to_string(s.quarter_turns) + " quarter turn(s)" +
                               (s.mirrored ? " after x -> -x, " : ", ") + (fast_engine ? "fast " : "reference ") +
                               to_string(m) + " " + to_string(q);
            EXPECT_EQ(step, trace.size()) << what << ": " << why;
            if (step < trace.size() && why.empty()) {
              ConformanceReport r = check_conformance(in.pslg, trace, options(m, theta));
              ADD_FAILURE() << what << ": " << describe(r);
            }
            ++runs;
            ConformanceReport r = check_conformance(in.pslg, trace, options(m, theta));
            EXPECT_TRUE(r.conforms) << what << ": " << describe(r);
            flipped += r.cocircular_flips > 0;
          }
    }
  EXPECT_EQ(runs, 6u * 8 * 2 * 2 * 2);
  EXPECT_GT(flipped, runs / 10) << "the inputs should make the replay follow other triangulations";
}

// The generated lattice families (ties, holes, cracks, small angles and the
// degenerate ones, at full size), each under all eight symmetries, with a
// random engine, method, order and theta.
RC_GTEST_PROP(CocircularCells, EnginesConformOnGeneratedPslgsUnderEverySymmetry, ()) {
  const Pslg p = validated(*rc::gen::resize(70, rc::gen::oneOf(gen::anyPslg(), gen::anyDegenerate())));
  const double theta = *rc::gen::element(20.0, 25.0, 30.0);
  const Method m = *rc::gen::element(Method::Centroid, Method::Midpoint);
  const QueueOrder q = *rc::gen::element(QueueOrder::Fifo, QueueOrder::Lifo);
  const bool fast_engine = *rc::gen::arbitrary<bool>();
  bool flipped = false;
  for (int k = 0; k < 8; ++k) {
    const gen::LatticeSymmetry s{k % 4, k >= 4};
    std::vector<Point> trace = trace_under(p, s, fast_engine, m, q, theta, 300);
    ConformanceReport r = check_conformance(p, trace, options(m, theta));
    flipped = flipped || r.cocircular_flips > 0;
    if (!r.conforms)
      RC_FAIL(std::string(fast_engine ? "fast " : "reference ") + to_string(m) + " " + to_string(q) + " theta " +
              std::to_string(theta) + " under " + std::to_string(s.quarter_turns) + " quarter turn(s)" +
              (s.mirrored ? " after x -> -x" : "") + ": " + describe(r));
  }
  RC_CLASSIFY(flipped, "followed another triangulation");
}

// ---- what is still rejected ----

// Six points of x^2 + y^2 = 25, no two opposite, as a polygon: one cocircular
// cell, 14 triangulations. Whatever the triangulation, every choice is the
// midpoint of two of the six points or the average of four of them (a
// terminal edge's or a second-longest edge's midpoint, a quad's centroid), so
// a point farther than the tolerance from all 15 + 15 of those is no choice
// under any triangulation: the triangles' centroids, for instance (the
// triangle-centroid bug), and a point of no rule.
TEST(CocircularCells, RejectsAPointThatIsNoChoiceUnderAnyTriangulation) {
  const std::vector<Point> six{{5, 0}, {4, 3}, {0, 5}, {-4, 3}, {-3, -4}, {3, -4}};
  Pslg p;
  p.vertices = six;
  for (int i = 0; i < 6; ++i) p.segments.push_back({i, (i + 1) % 6, 1});
  p = validated(p);
  std::vector<Point> anywhere;  // every choice of every triangulation is one of these
  for (int a = 0; a < 6; ++a)
    for (int b = a + 1; b < 6; ++b) {
      anywhere.push_back({(six[a].x + six[b].x) / 2, (six[a].y + six[b].y) / 2});
      for (int c = b + 1; c < 6; ++c)
        for (int d = c + 1; d < 6; ++d)
          anywhere.push_back({((six[a].x + six[b].x) + (six[c].x + six[d].x)) / 4, ((six[a].y + six[b].y) + (six[c].y + six[d].y)) / 4});
    }
  auto far_from_every_choice = [&](Point q) {
    for (const Point& c : anywhere)
      if (std::max(std::abs(c.x - q.x), std::abs(c.y - q.y)) < 1e-6) return false;
    return true;
  };
  std::vector<Point> wrong{{0.3, 0.7}};
  for (int a = 0; a < 6; ++a)
    for (int b = a + 1; b < 6; ++b)
      for (int c = b + 1; c < 6; ++c) wrong.push_back({(six[a].x + six[b].x + six[c].x) / 3, (six[a].y + six[b].y + six[c].y) / 3});
  const Mesh initial = reference::build_cdt(p);
  std::size_t tried = 0;
  for (Method m : {Method::Centroid, Method::Midpoint})
    for (const Point& q : wrong) {
      if (!far_from_every_choice(q)) continue;
      ++tried;
      ConformanceReport r = check_conformance(p, {q}, options(m, 30));
      ASSERT_FALSE(r.conforms) << "(" << q.x << ", " << q.y << ") accepted";
      EXPECT_EQ(r.failure->step, 0u);
      EXPECT_FALSE(r.cocircular_search_exhausted);
      EXPECT_EQ(r.cocircular_flips, 0) << "a failed search leaves the mesh as it was";
      EXPECT_EQ(r.failure->mesh.triangles, initial.triangles);
      EXPECT_NE(r.failure->reason.find("not the paper's choice"), std::string::npos) << r.failure->reason;
    }
  EXPECT_GE(tried, 30u);

  // And some of the quads' centroids are choices only under another triangulation than CGAL's.
  std::size_t only_elsewhere = 0;
  for (const Point& q : anywhere) {
    ConformanceOptions rigid = options(Method::Centroid, 30);
    rigid.follow_cocircular_flips = false;
    ConformanceReport followed = check_conformance(p, {q}, options(Method::Centroid, 30));
    ConformanceReport not_followed = check_conformance(p, {q}, rigid);
    EXPECT_TRUE(followed.conforms || !not_followed.conforms) << "following ties lost a choice";
    only_elsewhere += followed.conforms && !not_followed.conforms;
  }
  EXPECT_GT(only_elsewhere, 0u);
}

// The search is bounded: with a budget of a few triangles it gives up, says
// so, and leaves the mesh as it was.
TEST(CocircularCells, SearchBudgetIsReported) {
  const Pslg p = lattice_rectangle(4, 3);
  std::vector<Point> trace = trace_under(p, {3, false}, true, Method::Centroid, QueueOrder::Fifo, 30);
  ASSERT_FALSE(trace.empty());
  ConformanceOptions tight = options(Method::Centroid, 30);
  tight.cocircular_search_budget = 5;
  ConformanceReport r = check_conformance(p, trace, tight);
  ASSERT_FALSE(r.conforms);
  EXPECT_EQ(r.failure->step, 0u);
  EXPECT_TRUE(r.cocircular_search_exhausted);
  EXPECT_NE(describe(r).find("gave up"), std::string::npos) << describe(r);
  EXPECT_EQ(r.failure->mesh.triangles, reference::build_cdt(p).triangles);
}

// The budget counts every triangle the search looks at, wherever it runs out:
// in the scan of a cell's triangles, among the triangles across a terminal
// edge, or in the backward walk along the Lepp tree. The search is
// deterministic, so there is one smallest budget that follows step 0 of the
// quarter-turned rectangle's trace: every budget below it gives up, says so
// and leaves the mesh as it was (the fallback searches cannot follow this
// step); that budget and larger ones follow it.
TEST(CocircularCells, EveryBudgetBelowTheNeededOneGivesUpAndLeavesTheMesh) {
  const Pslg p = lattice_rectangle(4, 3);
  const std::vector<Point> trace = trace_under(p, {3, false}, true, Method::Centroid, QueueOrder::Fifo, 30);
  ASSERT_FALSE(trace.empty());
  const Mesh initial = reference::build_cdt(p);
  audit::ReplayRules rules;
  rules.method = Method::Centroid;
  rules.min_angle_deg = 30;
  rules.angle_tolerance_deg = ConformanceOptions().angle_tolerance_deg;
  auto follows = [&](std::size_t budget, bool& exhausted, Mesh& mesh) {
    rules.cocircular_search_budget = budget;
    audit::Replay replay(p, rules);
    audit::ReplayChoice choice;
    const bool ok = replay.match(trace[0], choice);
    exhausted = replay.cocircular_search_exhausted();
    mesh = replay.mesh();
    return ok;
  };
  bool exhausted = false;
  Mesh mesh;
  ASSERT_TRUE(follows(rules.cocircular_search_budget, exhausted, mesh));
  std::size_t needed = 0;
  while (!follows(needed, exhausted, mesh)) {
    ASSERT_TRUE(exhausted) << "budget " << needed << ": no match, yet the search did not run out";
    ASSERT_EQ(mesh.triangles, initial.triangles) << "budget " << needed << ": the mesh was left changed";
    ASSERT_LT(++needed, 20000u);
  }
  EXPECT_FALSE(exhausted);
  EXPECT_GT(needed, 5u) << "the step needs more than a handful of triangles looked at";
  for (std::size_t more : {needed + 1, 2 * needed}) {
    EXPECT_TRUE(follows(more, exhausted, mesh)) << more;
    EXPECT_FALSE(exhausted) << more;
  }
}

// The search compares edge lengths as the rest of the replay does: in doubles
// first, exactly where the squares overflow (at 2^600; at 2^510 only the longer
// edges' do) or fall below the filter's range (at 2^-600, where they underflow
// to zero). The quarter-turned rectangle and its trace scaled by a power of two
// (exact): the trace is followed through the cells at each scale, and a point
// moved by a millionth is not.
TEST(CocircularCells, SearchComparesLengthsExactlyWhereDoublesOverflowOrUnderflow) {
  const Pslg p = lattice_rectangle(4, 3);
  const std::vector<Point> trace = trace_under(p, {3, false}, true, Method::Centroid, QueueOrder::Fifo, 30);
  ASSERT_FALSE(trace.empty());
  for (int e : {600, 510, -600}) {
    Pslg scaled = p;
    for (Point& q : scaled.vertices) q = {std::ldexp(q.x, e), std::ldexp(q.y, e)};
    scaled = validated(scaled);
    std::vector<Point> t;
    for (const Point& q : trace) t.push_back({std::ldexp(q.x, e), std::ldexp(q.y, e)});
    ConformanceReport r = check_conformance(scaled, t, options(Method::Centroid, 30));
    EXPECT_TRUE(r.conforms) << e << ": " << describe(r);
    EXPECT_GT(r.cocircular_flips, 2) << e << ": followed through the cells";
    t[0].x += std::ldexp(1e-6, e);
    ConformanceReport moved = check_conformance(scaled, t, options(Method::Centroid, 30));
    ASSERT_FALSE(moved.conforms) << e;
    EXPECT_EQ(moved.failure->step, 0u) << describe(moved);
  }
}

}  // namespace
}  // namespace lepp::audit
