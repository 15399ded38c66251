// SPDX-License-Identifier: GPL-3.0-or-later
// The generators keep their promises: every PSLG validates untouched, triangles
// are counter-clockwise, terminal pairs are Delaunay terminal pairs (checked by
// the certifier, an independent implementation of the same conditions).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "gen_test_support.h"
#include "lepp/certify.h"
#include "lepp/gen.h"
#include "lepp/gen_precision.h"
#include "lepp/validate.h"

namespace lepp {
namespace {

using test::expect_validates_untouched;

RC_GTEST_PROP(Generators, AnyPslgValidates, ()) { expect_validates_untouched(*gen::anyPslg()); }
// The notch: a simple polygon (validates untouched) whose two segments from A make the
// outside a thin wedge: w lies right of A -> B, and B above the line A -> w.
RC_GTEST_PROP(Generators, UlpNotchIsASimplePolygonWithAThinWedgeAtA, ()) {
  const Pslg p = *gen::ulpNotch();
  expect_validates_untouched(p);
  const Point &a = p.vertices[0], &b = p.vertices[1], &w = p.vertices.back();
  auto cross = [](const Point& o, const Point& q, const Point& r) {  // exact: small multiples of one ulp
    return (q.x - o.x) * (r.y - o.y) - (q.y - o.y) * (r.x - o.x);
  };
  RC_ASSERT(cross(a, b, w) < 0);
  RC_ASSERT(cross(a, w, b) > 0);
}

RC_GTEST_PROP(Generators, WellShapedPslgValidatesWithAnglesAtLeast60, ()) {
  const Pslg p = *gen::wellShapedPslg();
  expect_validates_untouched(p);
  RC_ASSERT(gen::min_input_angle_deg(p) >= 60 - 1e-9);
}
RC_GTEST_PROP(Generators, ScaledPslgValidates, ()) { expect_validates_untouched(*gen::anyPslg(1.0 / 64)); }

RC_GTEST_PROP(Generators, TrianglesAreCounterClockwise, ()) {
  const auto t = *gen::triangle();
  const double o = (t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[1].y - t[0].y) * (t[2].x - t[0].x);  // exact: small integers
  RC_ASSERT(o > 0);
}

RC_GTEST_PROP(Generators, TerminalPairsAreDelaunayTerminalPairs, ()) {
  const gen::TerminalPair q = *gen::delaunayTerminalPair();
  // The quad a, d, b, c as a PSLG meshed by the two triangles: the certifier must
  // accept it (CCW, local Delaunay across ab) and find ab a terminal edge.
  Pslg p;
  p.vertices = {q.a, q.b, q.c, q.d};
  p.segments = {{0, 3, 0}, {3, 1, 0}, {1, 2, 0}, {2, 0, 0}};
  Mesh m;
  m.vertices = p.vertices;
  m.input_vertices = 4;
  m.triangles = {{0, 1, 2}, {1, 0, 3}};
  const auto r = certify::certify(p, m);
  if (!r.certified()) RC_FAIL(certify::format_report(r));
  RC_ASSERT(r.stats.terminal_pairs_checked == 1u);
}

}  // namespace
}  // namespace lepp
