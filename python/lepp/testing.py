# SPDX-License-Identifier: GPL-3.0-or-later
"""lepp.testing: Hypothesis strategies of valid PSLGs and assert_certified, so a Python
mesher's test suite states the paper's properties in three lines:

    from hypothesis import given
    from lepp.testing import pslgs, assert_certified

    @given(pslgs())
    def test_my_mesher(pslg):
        assert_certified(pslg, my_mesher(pslg, 25), min_angle=25, exempt_small_input_angles=True)

The families are those of lepp's RapidCheck generators (properties/gen/include/lepp/gen.h),
drawn the same way: every coordinate an integer of a small lattice times `scale` (a power of
two), so the predicates on them are exact in double and a shrunk counterexample is readable;
every PSLG of pslgs() and well_shaped_pslgs() passes lepp.validate without a warning
(degenerate_pslgs() may warn: a hole point on a segment removes nothing). Each dict has the `triangle` package's keys (vertices,
segments, segment_markers, holes; 0-based NumPy arrays) and 'family' ('gen:convex', ...).
Hypothesis shrinks them toward fewer vertices and smaller coordinates.
"""
import math

import numpy as np

try:
    from hypothesis import strategies as st
except ImportError as e:  # lepp itself does not need Hypothesis
    raise ImportError("lepp.testing needs Hypothesis (Debian: python3-hypothesis)") from e

from ._certify import certify

__all__ = ["pslgs", "well_shaped_pslgs", "convex_polygons", "star_polygons", "polygons_with_hole",
           "point_clouds_in_box", "boxes_with_cracks", "near_degenerate", "small_input_angles",
           "mirror_symmetric", "mirror_kites", "holes_on_boundaries", "threshold_angles", "degenerate_pslgs",
           "assert_certified"]


def _cross(o, a, b):
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def _dot(o, a, b):
    return (a[0] - o[0]) * (b[0] - o[0]) + (a[1] - o[1]) * (b[1] - o[1])


def _on_segment(a, b, p):
    return _cross(a, b, p) == 0 and _dot(p, a, b) <= 0


def _touch(a, b, c, d):
    d1, d2, d3, d4 = _cross(a, b, c), _cross(a, b, d), _cross(c, d, a), _cross(c, d, b)
    if ((d1 > 0 > d2) or (d1 < 0 < d2)) and ((d3 > 0 > d4) or (d3 < 0 < d4)):
        return True
    return _on_segment(a, b, c) or _on_segment(a, b, d) or _on_segment(c, d, a) or _on_segment(c, d, b)


def _lround(x):
    """C's lround: halves away from zero (Python's round() goes to even)."""
    return int(math.copysign(math.floor(abs(x) + 0.5), x))


class _Builder:
    """A PSLG on the lattice: vertices deduplicated; a ring or path sampled at every
    stride-th lattice point of its sides (vertices are added before segments)."""

    def __init__(self):
        self.points, self.segments, self.holes = [], [], []

    def vertex(self, p):
        p = (int(p[0]), int(p[1]))
        try:
            return self.points.index(p)
        except ValueError:
            self.points.append(p)
            return len(self.points) - 1

    @staticmethod
    def lattice_points(a, b, stride):
        dx, dy = b[0] - a[0], b[1] - a[1]
        g = math.gcd(abs(dx), abs(dy))
        if g == 0 or stride <= 0:
            return []
        return [(a[0] + k * (dx // g), a[1] + k * (dy // g)) for k in range(stride, g, stride)]

    def ring(self, corners, stride, marker):
        ids = []
        for i, a in enumerate(corners):
            b = corners[(i + 1) % len(corners)]
            ids.append(self.vertex(a))
            ids.extend(self.vertex(p) for p in self.lattice_points(a, b, stride))
        self.segments.extend((ids[i], ids[(i + 1) % len(ids)], marker) for i in range(len(ids)))

    def path(self, a, b, stride, marker):
        ids = [self.vertex(a)] + [self.vertex(p) for p in self.lattice_points(a, b, stride)] + [self.vertex(b)]
        self.segments.extend((ids[i], ids[i + 1], marker) for i in range(len(ids) - 1))

    def occupied(self, p):
        return p in self.points or any(_on_segment(self.points[s], self.points[t], p) for s, t, _ in self.segments)

    def blocked(self, a, b):
        if a == b or any(_on_segment(a, b, q) for q in self.points):
            return True
        return any(_touch(a, b, self.points[s], self.points[t]) for s, t, _ in self.segments)

    def build(self, family, scale, holes=None):
        seg = np.array([(s, t) for s, t, _ in self.segments], dtype=np.int32).reshape(-1, 2)
        return {
            "vertices": np.array(self.points, dtype=np.float64).reshape(-1, 2) * scale,
            "segments": seg,
            "segment_markers": np.array([m for _, _, m in self.segments], dtype=np.int32),
            "holes": np.array(self.holes if holes is None else holes, dtype=np.float64).reshape(-1, 2) * scale,
            "family": family,
        }


def _hull(pts):
    """Convex hull, counter-clockwise, no collinear points (monotone chain, exact)."""
    pts = sorted(set(pts))
    if len(pts) < 3:
        return pts
    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and _cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and _cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def _star(jitter_radius, regular_radius):
    """A polygon star-shaped around the origin (the regular one when the jittered one is not simple)."""
    n = len(jitter_radius)

    def make(jittered):
        v = []
        for i, (j, r) in enumerate(jitter_radius):
            a = (i + (j / 100.0 if jittered else 0)) * 2 * math.pi / n
            rr = r if jittered else regular_radius
            v.append((_lround(rr * math.cos(a)), _lround(rr * math.sin(a))))
        return v

    v = make(True)
    o = (0, 0)
    ok, total = True, 0.0
    for i in range(n):
        a, b = v[i], v[(i + 1) % n]
        ok = ok and _cross(o, a, b) > 0
        total += math.atan2(_cross(o, a, b), _dot(o, a, b))
    ok = ok and abs(total - 2 * math.pi) < 1e-6
    return v if ok else make(False)


def _ints(lo, hi):  # [lo, hi), as RapidCheck's inRange
    return st.integers(min_value=lo, max_value=hi - 1)


def _pairs(lo1, hi1, lo2, hi2, min_size=0, max_size=None):
    return st.lists(st.tuples(_ints(lo1, hi1), _ints(lo2, hi2)), min_size=min_size, max_size=max_size)


def convex_polygons(scale=1.0):
    """The hull of random points of [0,12]^2, magnified by m in [1, 4], every side sampled at
    each lattice point on it. 'gen:convex'"""
    @st.composite
    def gen(draw):
        raw = draw(_pairs(0, 13, 0, 13, max_size=20))
        m = draw(_ints(1, 5))
        hull = _hull(raw)
        if len(hull) < 3:
            hull = [(0, 0), (12, 0), (0, 12)]
        b = _Builder()
        b.ring([(x * m, y * m) for x, y in hull], 1, 1)
        return b.build("gen:convex", scale)
    return gen()


def star_polygons(scale=1.0):
    """A star-shaped polygon with 4 to 12 corners at radii 12 to 32, magnified by m in [1, 3],
    sampled at every lattice point of its sides. 'gen:star'"""
    @st.composite
    def gen(draw):
        n = draw(_ints(4, 13))
        jr = draw(_pairs(-40, 41, 12, 33, n, n))
        m = draw(_ints(1, 4))
        b = _Builder()
        b.ring([(x * m, y * m) for x, y in _star(jr, 24)], 1, 1)
        return b.build("gen:star", scale)
    return gen()


def polygons_with_hole(scale=1.0):
    """A star-shaped polygon (6 to 12 corners, radii 24 to 40) with a star-shaped hole (4 to 6
    corners, radii 4 to 8) around the origin, hole point at the origin. 'gen:hole'"""
    @st.composite
    def gen(draw):
        n, k = draw(_ints(6, 13)), draw(_ints(4, 7))
        outer = draw(_pairs(-40, 41, 24, 41, n, n))
        inner = draw(_pairs(-20, 21, 4, 9, k, k))
        m = draw(_ints(1, 4))
        b = _Builder()
        b.ring([(x * m, y * m) for x, y in _star(outer, 32)], 1, 1)
        b.ring([(x * m, y * m) for x, y in _star(inner, 6)], 1, 2)
        b.holes.append((0, 0))
        return b.build("gen:hole", scale)
    return gen()


def point_clouds_in_box(scale=1.0):
    """The box [0,W]x[0,H] (W, H in [2, 32]), its sides sampled every `stride` lattice points
    (0: corners only), 0 to 40 interior points. 'gen:cloud'"""
    @st.composite
    def gen(draw):
        w, h, stride = draw(_ints(2, 33)), draw(_ints(2, 33)), draw(_ints(0, 5))
        raw = draw(_pairs(0, 64, 0, 64, max_size=40))
        b = _Builder()
        b.ring([(0, 0), (w, 0), (w, h), (0, h)], stride, 1)
        for x, y in raw:
            p = (1 + x % (w - 1), 1 + y % (h - 1))
            if not b.occupied(p):
                b.vertex(p)
        return b.build("gen:cloud", scale)
    return gen()


def boxes_with_cracks(scale=1.0):
    """The box [0,W]x[0,H] (W, H in [8, 32]) with up to 6 dangling segments between interior
    lattice points (one touching an earlier one or a vertex is dropped) and a few interior
    points. 'gen:cracks'"""
    @st.composite
    def gen(draw):
        w, h = draw(_ints(8, 33)), draw(_ints(8, 33))
        cracks = draw(st.lists(st.tuples(*[_ints(0, 64)] * 4), max_size=6))
        raw = draw(_pairs(0, 64, 0, 64, max_size=6))
        b = _Builder()
        b.ring([(0, 0), (w, 0), (w, h), (0, h)], 0, 1)

        def inside(x, y):
            return (1 + x % (w - 1), 1 + y % (h - 1))

        for c in cracks:
            p, q = inside(c[0], c[1]), inside(c[2], c[3])
            if not b.blocked(p, q):
                b.path(p, q, 0, 3)
        for x, y in raw:
            p = inside(x, y)
            if not b.occupied(p):
                b.vertex(p)
        return b.build("gen:cracks", scale)
    return gen()


def near_degenerate(scale=1.0):
    """One of: a collinear run of points across a box; the lattice points of a circle in a box;
    a full grid of interior points; a crack with a row of points at distances k / |crack| from
    its line. 'gen:collinear', 'gen:cocircular', 'gen:grid', 'gen:close'"""
    @st.composite
    def collinear(draw):
        w, step = draw(_ints(4, 41)), draw(_ints(1, 4))
        b = _Builder()
        b.ring([(0, 0), (w, 0), (w, w), (0, w)], 0, 1)
        for x in range(step, w, step):
            b.vertex((x, w // 2))
        for x in range(step, w, step):
            if not b.occupied((x, x)):
                b.vertex((x, x))
        return b.build("gen:collinear", scale)

    @st.composite
    def cocircular(draw):
        r2 = (25, 50, 65, 85, 125, 325, 425)[draw(_ints(0, 7))]
        center = draw(st.booleans())
        r = math.isqrt(r2)
        b = _Builder()
        b.ring([(-r - 2, -r - 2), (r + 2, -r - 2), (r + 2, r + 2), (-r - 2, r + 2)], 0, 1)
        for x in range(-r, r + 1):
            for y in range(-r, r + 1):
                if x * x + y * y == r2:
                    b.vertex((x, y))
        if center:
            b.vertex((0, 0))
        return b.build("gen:cocircular", scale)

    @st.composite
    def grid(draw):
        a, c = draw(_ints(1, 9)), draw(_ints(1, 9))
        b = _Builder()
        b.ring([(0, 0), (a + 1, 0), (a + 1, c + 1), (0, c + 1)], 1, 1)
        for x in range(1, a + 1):
            for y in range(1, c + 1):
                b.vertex((x, y))
        return b.build("gen:grid", scale)

    @st.composite
    def close(draw):
        w = draw(_ints(6, 41))
        b = _Builder()
        b.ring([(0, 0), (w, 0), (w, w), (0, w)], 0, 1)
        b.path((1, 1), (w - 2, w - 3), 0, 3)
        for k in range(1, w - 3):
            b.vertex((1 + k, 1 + k))
        return b.build("gen:close", scale)

    return st.one_of(collinear(), cocircular(), grid(), close())


def small_input_angles(scale=1.0):
    """A wedge of angle phi in [1, 59] degrees at the origin, sides of length L in [64, 1024],
    as a convex polygon (the side on the x axis sampled every L/8) or as two cracks inside a
    box. 'gen:wedge', 'gen:wedge-cracks'"""
    @st.composite
    def gen(draw):
        phi, length, cracks = draw(_ints(1, 60)), draw(_ints(64, 1025)), draw(st.booleans())
        a = phi * math.pi / 180
        L = length
        o, p1 = (0, 0), (L, 0)
        p2 = (_lround(L * math.cos(a)), _lround(L * math.sin(a)))
        if p2[1] == 0:
            p2 = (p2[0], 1)
        if cracks:
            b = _Builder()
            b.ring([(-L // 2, -L // 2), (L + L // 2, -L // 2), (L + L // 2, L + L // 2), (-L // 2, L + L // 2)], 0, 1)
            b.path(o, p1, L // 8, 3)
            b.path(o, p2, 0, 3)
            return b.build("gen:wedge-cracks", scale)
        q = (_lround(1.3 * L * math.cos(a / 2)), _lround(1.3 * L * math.sin(a / 2)))
        convex = _cross(o, p1, q) > 0 and _cross(p1, q, p2) > 0 and _cross(q, p2, o) > 0
        ring = [o, p1, q, p2] if convex else [o, p1, p2]
        corners = []
        for i, c in enumerate(ring):
            corners.append(c)
            if i == 0:
                corners.extend((k * L // 8, 0) for k in range(1, 8))
        b = _Builder()
        b.ring(corners, 0, 1)
        return b.build("gen:wedge", scale)
    return gen()


def pslgs(scale=1.0):
    """Any of the families above (lepp::gen::anyPslg)."""
    return st.one_of(convex_polygons(scale), star_polygons(scale), polygons_with_hole(scale),
                     point_clouds_in_box(scale), boxes_with_cracks(scale), near_degenerate(scale),
                     small_input_angles(scale))


def well_shaped_pslgs(scale=1.0):
    """PSLGs whose input angles are all >= 60 degrees (the class of the paper's termination
    results): boxes with interior points, regular polygons with 6 to 12 sides, boxes with a
    square hole (lepp::gen::wellShapedPslg). 'gen:cloud', 'gen:regular', 'gen:box-hole'"""
    @st.composite
    def regular(draw):
        n, radius, stride = draw(_ints(6, 13)), draw(_ints(8, 33)), draw(_ints(0, 3))
        b = _Builder()
        b.ring(_star([(0, radius)] * n, radius), stride, 1)
        return b.build("gen:regular", scale)

    @st.composite
    def box_hole(draw):
        w, h, hx, hy = draw(_ints(4, 33)), draw(_ints(4, 33)), draw(_ints(0, 32)), draw(_ints(0, 32))
        hw, hh, stride = draw(_ints(1, 16)), draw(_ints(1, 16)), draw(_ints(0, 3))
        b = _Builder()
        b.ring([(0, 0), (w, 0), (w, h), (0, h)], stride, 1)
        x0, y0 = 1 + hx % max(1, w - hw - 1), 1 + hy % max(1, h - hh - 1)
        x1, y1 = min(x0 + hw, w - 1), min(y0 + hh, h - 1)
        if x1 > x0 and y1 > y0:
            b.ring([(x0, y0), (x1, y0), (x1, y1), (x0, y1)], stride, 2)
            return b.build("gen:box-hole", scale, holes=[(x0 + 0.5, y0 + 0.5)])
        return b.build("gen:box-hole", scale)

    return st.one_of(point_clouds_in_box(scale), regular(), box_hole())


# ---- the degenerate families (properties/gen/include/lepp/gen_degenerate.h) -------------
# Where docs/ALGORITHM.md's decisions meet their boundaries: exact ties in edge length,
# orientation and in-circle exactly zero, angles at a threshold, hole points on vertices,
# segments and unconstrained edges. Some make validation warn (a hole point on a segment
# removes nothing): run them through lepp.validate before a mesher sees them.

def mirror_symmetric(scale=1.0):
    """A box [-W, W] x [-H, H] (sides sampled every `stride` lattice points) and up to 12
    points of the quadrant x, y > 0 with their images under x -> -x, y -> -y, both, or the
    half turn: equal edge lengths and cocircular quadruples everywhere. 'gen:mirror'"""
    @st.composite
    def gen(draw):
        w, h, stride, group = draw(_ints(3, 17)), draw(_ints(3, 17)), draw(_ints(0, 3)), draw(_ints(0, 4))
        raw = draw(_pairs(0, 64, 0, 64, max_size=12))
        b = _Builder()
        b.ring([(-w, -h), (w, -h), (w, h), (-w, h)], stride, 1)
        for rx, ry in raw:
            x, y = 1 + rx % (w - 1), 1 + ry % (h - 1)
            orbit = [(x, y)]
            if group in (0, 2):
                orbit.append((-x, y))
            if group in (1, 2):
                orbit.append((x, -y))
            if group in (2, 3):
                orbit.append((-x, -y))
            for p in orbit:
                if not b.occupied(p):
                    b.vertex(p)
        return b.build("gen:mirror", scale)
    return gen()


def mirror_kites(scale=1.0):
    """Kites about their diagonal (-a, 0)-(a, 0) with apexes (c, h1), (c, -h2) (h1 = h2: the
    quad centroid exactly on the diagonal), up to 3 interior points on an axis. 'gen:kite'"""
    @st.composite
    def gen(draw):
        a, c, h1, h2 = draw(_ints(2, 33)), draw(_ints(0, 33)), draw(_ints(1, 57)), draw(_ints(1, 57))
        equal = draw(st.booleans())
        inner = draw(st.lists(_ints(0, 256), max_size=3))
        A, C, H1 = a, c % a, h1
        H2 = h1 if equal else h2
        b = _Builder()
        b.ring([(-A, 0), (C, -H2), (A, 0), (C, H1)], 1, 1)
        for i in inner:
            low = min(H1, H2)
            p = (-A + 1 + (i >> 1) % (2 * A - 1), 0) if i & 1 else (C, -low + 1 + (i >> 1) % (2 * low - 1))
            if not b.occupied(p):
                b.vertex(p)
        return b.build("gen:kite", scale)
    return gen()


def holes_on_boundaries(scale=1.0):
    """A box around a triangle ring with a free vertex inside, and one hole point inside a
    triangle, on an unconstrained edge, on a ring vertex, on the free vertex, on a segment or
    on the outer boundary (only the first two remove the ring's inside). 'gen:hole-on'"""
    @st.composite
    def gen(draw):
        k, where, jx, jy = draw(_ints(2, 9)), draw(_ints(0, 6)), draw(_ints(0, 4)), draw(_ints(0, 4))
        K = 4 * k
        b = _Builder()
        b.ring([(0, 0), (2 * K, 0), (2 * K, 2 * K), (0, 2 * K)], 0, 1)
        p0, p1, p2 = (K // 2, K // 2), (K + K // 2, K // 2 + 2 * (jx % 2)), (K, K + K // 2 + 2 * (jy % 2))
        q = (K, K)
        b.vertex(q)
        b.ring([p0, p1, p2], 0, 2)
        hole = [(q[0], q[1] - 1), ((q[0] + p0[0]) // 2, (q[1] + p0[1]) // 2), p1, q,
                ((p1[0] + p2[0]) // 2, (p1[1] + p2[1]) // 2), (K, 0)][where]
        b.holes.append(hole)
        return b.build("gen:hole-on", scale)
    return gen()


def threshold_angles(scale=1.0):
    """Input angles exactly at or next to the thresholds compared: a right isosceles corner
    (45 and 90 degrees exactly), a sliver of slope 1/L, a boundary bent by one lattice unit
    (near 180, convex and reflex), an almost right corner. 'gen:angles'"""
    @st.composite
    def gen(draw):
        kind, L, stride = draw(_ints(0, 6)), draw(_ints(4, 33)), draw(_ints(0, 3))
        ring = [
            [(0, 0), (L, 0), (0, L)],
            [(0, 0), (L, 0), (L, L), (0, 2 * L)],
            [(0, 0), (L, 0), (L, 1)],
            [(0, 0), (L, 1), (2 * L, 0), (2 * L, L), (0, L)],
            [(0, 0), (L, -1), (2 * L, 0), (2 * L, L), (0, L)],
            [(0, 0), (L, 0), (1, L)],
        ][kind]
        b = _Builder()
        b.ring(ring, stride, 1)
        return b.build("gen:angles", scale)
    return gen()


def degenerate_pslgs(scale=1.0):
    """Any degenerate family above, or near_degenerate's (lepp::gen::anyDegenerate)."""
    return st.one_of(mirror_symmetric(scale), mirror_kites(scale), holes_on_boundaries(scale),
                     threshold_angles(scale), near_degenerate(scale))


def assert_certified(pslg, mesh, min_angle=0, **options):
    """Certifies mesh (a lepp.Mesh or a mesh dict) of pslg exactly (lepp.certify, with its
    keyword options) and raises AssertionError with the report and the first violations when
    it is not certified. Returns the lepp.Report."""
    report = certify(pslg, mesh, min_angle=min_angle, **options)
    if not report.ok:
        first = "\n".join(f"  {v['reason']}: {v['message']}" for v in report.violations[:5])
        family = pslg.get("family", "") if isinstance(pslg, dict) else ""
        raise AssertionError(f"mesh not certified{' (' + family + ')' if family else ''}:\n{first}\n\n{report.text}")
    return report
