// SPDX-License-Identifier: GPL-3.0-or-later
// The degenerate families (lepp/gen_degenerate.h) keep their promises: each PSLG
// validates (hole points on segments and vertices only warn), and each family
// reaches the boundary cases it exists for; a family that silently stopped making
// them (a mirror kite that is no longer mirrored, a hole point nudged off its edge)
// would leave the differential tests steering around the corner again.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstdint>
#include <set>
#include <string>

#include "gen_test_support.h"
#include "lepp/gen.h"
#include "lepp/gen_degenerate.h"
#include "lepp/validate.h"

namespace lepp {
namespace {

// n values of a generator, from fixed seeds: for "the family makes case X" checks.
template <typename T>
std::vector<T> sample(const rc::Gen<T>& gen, int n) {
  std::vector<T> out;
  for (int i = 0; i < n; ++i) out.push_back(gen(rc::Random(static_cast<std::uint64_t>(1000 + i)), i % 100).value());
  return out;
}

// Exact on the lattice: the families draw small integers.
double cross(const Point& o, const Point& a, const Point& b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

RC_GTEST_PROP(DegenerateGenerators, EveryFamilyValidates, ()) {
  // Only hole points on a segment, a vertex or outside may warn (they remove nothing).
  test::expect_validates_untouched(*gen::withPermutedIds(gen::anyDegenerate()), [](const std::string& w) {
    return w.find("removes nothing") != std::string::npos;
  });
}

TEST(DegenerateGenerators, KitesIncludeMirrorKitesAndOthers) {
  int mirror = 0, other = 0;
  for (const Pslg& p : sample(gen::mirrorKite(), 300)) {
    // The ring is A (-a, 0), D (c, -h2), B (a, 0), C (c, h1): vertices 0..3 before the side samples.
    double lo = 0, hi = 0;
    for (const Point& v : p.vertices) lo = std::min(lo, v.y), hi = std::max(hi, v.y);
    (hi == -lo ? mirror : other) += 1;
  }
  EXPECT_GT(mirror, 30);
  EXPECT_GT(other, 30);
}

TEST(DegenerateGenerators, HolePointsLandOnEveryKindOfPlace) {
  std::set<std::string> kinds;
  for (const Pslg& p : sample(gen::holeOnBoundary(), 300)) {
    ASSERT_EQ(p.holes.size(), 1u);
    const Point& h = p.holes[0];
    std::string kind = "inside";
    for (const Point& v : p.vertices)
      if (v == h) kind = "vertex";
    for (const Segment& s : p.segments) {
      const Point &a = p.vertices[static_cast<std::size_t>(s.a)], &b = p.vertices[static_cast<std::size_t>(s.b)];
      if (kind == "inside" && cross(a, b, h) == 0 && (h.x - a.x) * (h.x - b.x) + (h.y - a.y) * (h.y - b.y) < 0) kind = "segment";
    }
    // The midpoint of the free vertex (the last one) and the ring's first corner: an unconstrained edge.
    const Point &q = p.vertices[4], &p0 = p.vertices[5];
    if (kind == "inside" && h.x * 2 == q.x + p0.x && h.y * 2 == q.y + p0.y) kind = "unconstrained edge";
    kinds.insert(kind);
  }
  EXPECT_EQ(kinds, (std::set<std::string>{"inside", "vertex", "segment", "unconstrained edge"}));
}

// Terminal pairs: ab strictly the longest edge of both triangles, for any id order.
RC_GTEST_PROP(DegenerateGenerators, TerminalPairEdgeStrictlyLongest, ()) {
  const gen::TerminalPair q = *gen::delaunayTerminalPair();
  auto len2 = [](const Point& u, const Point& v) { return (u.x - v.x) * (u.x - v.x) + (u.y - v.y) * (u.y - v.y); };
  const double ab = len2(q.a, q.b);
  RC_ASSERT(len2(q.a, q.c) < ab && len2(q.b, q.c) < ab && len2(q.a, q.d) < ab && len2(q.b, q.d) < ab);
}

}  // namespace
}  // namespace lepp
