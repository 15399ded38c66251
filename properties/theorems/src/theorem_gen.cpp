// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind lepp/theorems/theorem_gen.h: RapidCheck generators of the inputs the
// paper's statements talk about.
#include "lepp/theorems/theorem_gen.h"

namespace lepp::theorems::gen {

namespace {
rc::Gen<GridPoint> point(int lo, int hi) {
  return rc::gen::apply([](std::int64_t x, std::int64_t y) { return GridPoint{x, y}; },
                        rc::gen::inRange<std::int64_t>(lo, hi + 1), rc::gen::inRange<std::int64_t>(lo, hi + 1));
}
bool degenerate(const GridTriangle& t) {
  return (t.p[1].x - t.p[0].x) * (t.p[2].y - t.p[0].y) - (t.p[1].y - t.p[0].y) * (t.p[2].x - t.p[0].x) == 0;
}
}  // namespace

rc::Gen<GridTriangle> triangle(int range) {
  auto any = rc::gen::apply([](GridPoint a, GridPoint b, GridPoint c) { return GridTriangle{{a, b, c}}; },
                            point(-range, range), point(-range, range), point(-range, range));
  // Isosceles triangles (apex on the perpendicular bisector of an even base), where ties live.
  auto isosceles = rc::gen::exec([range] {
    // Base a b = m -+ 4h, apex m + k perp(h): k < 4 gives the thin obtuse ones (BC = CA), k > 4 the tall ones.
    GridPoint m = *point(-range / 2, range / 2);
    GridPoint h = *point(-range / 8, range / 8);
    std::int64_t k = *rc::gen::inRange<std::int64_t>(1, 13);
    GridPoint a{m.x + 4 * h.x, m.y + 4 * h.y}, b{m.x - 4 * h.x, m.y - 4 * h.y}, c{m.x - k * h.y, m.y + k * h.x};
    return GridTriangle{{a, b, c}};
  });
  return rc::gen::suchThat(rc::gen::weightedOneOf<GridTriangle>({{3, any}, {1, isosceles}}),
                           [](const GridTriangle& t) { return !degenerate(t); });
}

rc::Gen<TerminalQuad> terminal_quad() {
  auto raw = rc::gen::exec([] {
    const std::int64_t n = *rc::gen::inRange<std::int64_t>(2, 17);
    GridPoint dir = *rc::gen::suchThat(point(-6, 6), [](const GridPoint& d) { return d.x != 0 || d.y != 0; });
    GridPoint origin = *point(-20, 20);
    auto at = [&](std::int64_t i, std::int64_t j, GridPoint e) {
      // origin + i (p, q) + j (-q, p) + e
      return GridPoint{origin.x + i * dir.x - j * dir.y + e.x, origin.y + i * dir.y + j * dir.x + e.y};
    };
    const GridPoint zero{0, 0};
    std::int64_t ci = *rc::gen::inRange<std::int64_t>(0, n + 1), cj = *rc::gen::inRange<std::int64_t>(1, n);
    GridPoint ce = *rc::gen::weightedOneOf<GridPoint>({{2, rc::gen::just(zero)}, {1, point(-2, 2)}});
    bool mirror = *rc::gen::weightedElement<bool>({{7, false}, {1, true}});
    std::int64_t di = mirror ? ci : *rc::gen::inRange<std::int64_t>(0, n + 1);
    std::int64_t dj = mirror ? cj : *rc::gen::inRange<std::int64_t>(1, n);
    GridPoint de = mirror ? zero : *rc::gen::weightedOneOf<GridPoint>({{2, rc::gen::just(zero)}, {1, point(-2, 2)}});
    return TerminalQuad{at(n, 0, zero), at(0, 0, zero), at(ci, cj, ce), at(di, -dj, de)};
  });
  return rc::gen::suchThat(raw, [](const TerminalQuad& q) { return is_delaunay_terminal_pair(q); });
}

rc::Gen<TerminalQuad> lemma11_corner_quad() {
  auto raw = rc::gen::exec([] {
    using I = __int128;
    const I L = *rc::gen::inRange<std::int64_t>(4, 13);
    const I cx = *rc::gen::inRange<std::int64_t>(1, static_cast<std::int64_t>(L / 2) + 1);
    const I cy = *rc::gen::inRange<std::int64_t>(1, static_cast<std::int64_t>(L));
    // B = (0, 0), A = (L, 0), C = (cx, cy); circumcentre (L/2, p/q); U, the reflection of B across
    // line AO, is (L (2Dn - N), 4 L^2 q p) / Dn with N = 2 L^2 q^2, Dn = L^2 q^2 + 4 p^2.
    const I q = 2 * cy, p = cx * cx - L * cx + cy * cy;
    const I N = 2 * L * L * q * q, Dn = L * L * q * q + 4 * p * p;
    I ux = L * (2 * Dn - N), uy = 4 * L * L * q * p;
    I ax = L * Dn, ccx = cx * Dn, ccy = cy * Dn;
    bool at_w = *rc::gen::arbitrary<bool>();
    if (at_w) ux = ax - ux;  // W, the mirror image of U across x = L/2
    auto g = [](I a, I b) {
      if (a < 0) a = -a;
      if (b < 0) b = -b;
      while (b) {
        I t = a % b;
        a = b;
        b = t;
      }
      return a;
    };
    I k = g(g(g(ax, ccx), g(ccy, ux)), uy);
    if (k == 0) k = 1;
    auto v = [&](I x) { return static_cast<std::int64_t>(x / k); };
    return TerminalQuad{{v(ax), 0}, {0, 0}, {v(ccx), v(ccy)}, {v(ux), v(uy)}};
  });
  return rc::gen::suchThat(raw, [](const TerminalQuad& q) { return is_delaunay_terminal_pair(q); });
}

rc::Gen<std::vector<GridPoint>> mesh_points() {
  return rc::gen::exec([] {
    const int count = *rc::gen::inRange(4, 41);
    return *rc::gen::container<std::vector<GridPoint>>(count, point(0, 300));
  });
}

rc::Gen<Theorem2EqualityInput> theorem2_equality() {
  return rc::gen::exec([] {
    Theorem2EqualityInput in;
    in.A = *point(-20, 20);
    in.B = *rc::gen::suchThat(point(-20, 20), [&](const GridPoint& b) { return b.x != in.A.x || b.y != in.A.y; });
    in.s_den = *rc::gen::inRange<std::int64_t>(1, 20);
    in.s_num = *rc::gen::inRange<std::int64_t>(-in.s_den + 1, in.s_den);
    bool at_apex = *rc::gen::weightedElement<bool>({{7, false}, {1, true}});
    in.d_den = *rc::gen::inRange<std::int64_t>(1, 100);
    in.dx = at_apex ? 0 : *rc::gen::inRange<std::int64_t>(-3, 4);
    in.dy = at_apex ? 0 : *rc::gen::inRange<std::int64_t>(-3, 4);
    return in;
  });
}

}  // namespace lepp::theorems::gen
