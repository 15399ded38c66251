// SPDX-License-Identifier: GPL-3.0-or-later
// The replay keeps each face's facts (longest edges, bad or not) while the face
// keeps its vertices and region (face_facts.h): white-box, every fact read from
// the cache is its computation at every step of ten traces, under both length
// readings; the searches answer the same with the cache and without, under the
// readings that allow near ties of the lengths and the threshold; an entry
// follows a face changed in place, a face given another region, and a face whose
// FaceInfo was copied from another's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "trace_cases.h"

namespace lepp::audit::replay_detail {
namespace {

using namespace trace_cases;

struct Restore {
  ~Restore() { Replayer::cache_face_facts = true; }
};

// Two regions with their own size bounds (region_area_bounds): a face's region
// is one of its facts' keys.
Case two_regions() {
  Pslg p;
  p.vertices = {{0, 0}, {2, 0}, {2, 1}, {0, 1}, {1, 0}, {1, 1}};
  p.segments = {{0, 4, 0}, {4, 1, 0}, {1, 2, 0}, {2, 5, 0}, {5, 3, 0}, {3, 0, 0}, {4, 5, 0}};
  p.regions = {{{0.5, 0.5}, 1, 0.02}, {{1.5, 0.5}, 2, 0.2}};
  std::vector<std::string> warnings;
  return {"two regions", validate(p, warnings), Method::Centroid, 25};
}

TEST(FaceFacts, EveryFactIsItsComputationAtEveryStep) {
  std::vector<Case> all = cases();
  all.push_back(two_regions());
  std::int64_t restarts = 0;
  std::size_t checked = 0;
  for (const Case& c : all) {
    RefineOptions options;
    options.method = c.method;
    options.min_angle_deg = c.theta;
    options.max_steiner = 80;
    options.trace = true;
    options.region_area_bounds = c.name == "two regions";
    const RefineResult run = fast::refine(c.pslg, options);
    ASSERT_FALSE(run.trace.empty()) << c.name;
    ReplayRules rules = rules_of(c);
    rules.region_area_bounds = options.region_area_bounds;
    Replayer replayer(c.pslg, rules);
    for (std::size_t i = 0; i <= run.trace.size(); ++i) {
      for (const bool ties : {false, true}) {
        LengthTiesWithinRounding reading(ties);
        for (FH f : replayer.tr.cdt.finite_face_handles()) {
          if (!in_domain(replayer.tr, f)) continue;
          for (int e = 0; e < 3; ++e) EXPECT_EQ(replayer.longest(f, e), is_longest(f, e)) << c.name << ", step " << i;
          EXPECT_EQ(replayer.maybe_bad(f), replayer.judge_bad(f)) << c.name << ", step " << i;
          ++checked;
        }
      }
      if (i == run.trace.size()) break;
      ReplayChoice choice;
      ASSERT_TRUE(replayer.match(run.trace[i].point, choice)) << c.name << ", step " << i + 1;
      replayer.insert(run.trace[i].point, choice);
    }
    restarts += replayer.face_facts().restarts();
  }
  EXPECT_GT(checked, 10000u);
  // Faces were changed in place after their facts were kept (else the entries'
  // check of the vertices was never needed here).
  EXPECT_GT(restarts, 100);
}

// The two readings that ask the facts again with near ties: the threshold's (a
// flag of the replayer's own) and the lengths' (a thread-local flag): allowed, the
// searches that miss run again under them.
TEST(FaceFacts, TheSearchesAnswerTheSameWithoutTheCache) {
  Restore restore;
  for (const Case& c : cases()) {
    const RefineResult run = traced_run(c);
    Replayer cached(c.pslg, rules_of(c)), computing(c.pslg, rules_of(c));
    for (Replayer* r : {&cached, &computing}) {
      r->allow(Deviation::InexactThreshold);
      r->allow(Deviation::InexactLength);
    }
    const std::size_t replayed =
        replay_both(c, run, cached, computing, [](bool first) { Replayer::cache_face_facts = first; });
    EXPECT_EQ(replayed, run.trace.size()) << c.name << ": the trace is replayed to its end";
  }
}

// The smallest mesh: a triangle and a point inside it, for the entries' bookkeeping.
struct Small {
  Replayer replayer;
  Small() : replayer(make(), ReplayRules{}) {}
  static Pslg make() {
    Pslg p;
    p.vertices = {{0, 0}, {4, 0}, {0, 3}, {1, 1}};
    p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 0, 0}};
    std::vector<std::string> warnings;
    return validate(p, warnings);
  }
  std::vector<FH> faces() {
    std::vector<FH> out;
    for (FH f : replayer.tr.cdt.finite_face_handles()) out.push_back(f);
    return out;
  }
};

TEST(FaceFacts, AFaceChangedInPlaceStartsAfresh) {
  Small s;
  FaceFacts facts;
  const FH f = s.faces().front();
  FaceFacts::Facts& e = facts.of(f);
  e.bad[0] = 1;
  EXPECT_EQ(&facts.of(f), &e) << "the same face, the same entry";
  EXPECT_EQ(facts.of(f).bad[0], 1);
  // A flip changes both faces in place (CGAL keeps their handles).
  int i = 0;
  while (f->is_constrained(i) || s.replayer.tr.cdt.is_infinite(f->neighbor(i))) ++i;
  s.replayer.tr.cdt.tds().flip(f, i);
  EXPECT_EQ(facts.of(f).bad[0], FaceFacts::kUnknown) << "other vertices: the kept fact is dropped";
  EXPECT_EQ(facts.restarts(), 1);
}

TEST(FaceFacts, AFaceGivenAnotherRegionStartsAfresh) {
  Small s;
  FaceFacts facts;
  const FH f = s.faces().front();
  facts.of(f).longest[1] = 5;
  f->info().region = 1;
  EXPECT_EQ(facts.of(f).longest[1], FaceFacts::kUnknown);
  EXPECT_EQ(facts.restarts(), 1);
}

TEST(FaceFacts, ACopiedFaceInfoGivesTheFaceItsOwnEntry) {
  Small s;
  FaceFacts facts;
  const std::vector<FH> faces = s.faces();
  ASSERT_GE(faces.size(), 2u);
  const FH a = faces[0], b = faces[1];
  facts.of(a).bad[0] = 1;
  b->info() = a->info();  // as the reference engine copies a side's info
  EXPECT_EQ(facts.of(b).bad[0], FaceFacts::kUnknown);
  facts.of(b).bad[0] = 0;
  EXPECT_EQ(facts.of(a).bad[0], 1) << "a keeps its entry";
  EXPECT_EQ(facts.of(b).bad[0], 0) << "b has its own";
  EXPECT_EQ(facts.restarts(), 0) << "no entry taken from one face by the other";
}

TEST(FaceFacts, ACopyStartsEmpty) {
  Small s;
  FaceFacts facts;
  const FH f = s.faces().front();
  facts.of(f).bad[0] = 1;
  FaceFacts copy = facts;
  EXPECT_EQ(copy.of(f).bad[0], FaceFacts::kUnknown);
  FaceFacts assigned;
  assigned.of(f).bad[0] = 0;
  assigned = facts;
  EXPECT_EQ(assigned.of(f).bad[0], FaceFacts::kUnknown);
}

// A terminal pair across an unconstrained edge, one side bad at 35 degrees (base
// angles 32), the other good (59): the walk from either side never crosses the
// terminal edge, so the Lepp is the bad triangle, then the other, each once. Both
// mirror images: one of them starts the walk from the good side.
TEST(FaceFacts, TheWalkStaysOnItsSideOfTheTerminalEdge) {
  for (const double sign : {1.0, -1.0}) {
    SCOPED_TRACE(sign);
    const double h1 = std::tan(59 * M_PI / 180), h2 = std::tan(32 * M_PI / 180);
    Pslg raw;
    raw.vertices = {{0, 0}, {1, -sign * h2}, {2, 0}, {1, sign * h1}};
    raw.segments = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}, {3, 0, 0}};
    std::vector<std::string> warnings;
    const Pslg pslg = validate(raw, warnings);
    ReplayRules rules;
    rules.min_angle_deg = 35;
    Replayer replayer(pslg, rules);
    std::size_t domain = 0;
    for (FH f : replayer.tr.cdt.finite_face_handles()) domain += in_domain(replayer.tr, f);
    ASSERT_EQ(domain, 2u);
    // The paper's choice (Select Point splits a constrained edge of the flat side).
    std::size_t total = 0;
    const std::vector<ReplayChoice> all = replayer.all_choices({1, 0}, 1, total);
    ASSERT_EQ(all.size(), 1u);
    ReplayChoice choice;
    ASSERT_TRUE(replayer.match(all[0].point, choice));
    ASSERT_EQ(choice.lepp.size(), 2u);
    EXPECT_NE(choice.lepp[0], choice.lepp[1]);
    EXPECT_EQ(choice.bad, choice.lepp[0]);
    EXPECT_NE(std::find(choice.bad.begin(), choice.bad.end(), 1), choice.bad.end()) << "the bad triangle is the flat one";
  }
}

}  // namespace
}  // namespace lepp::audit::replay_detail
