// SPDX-License-Identifier: GPL-3.0-or-later
// RapidCheck generators of the degenerate inputs where docs/ALGORITHM.md's
// decisions meet their boundaries (issue 13, item 3): exact ties in edge length
// (decided by ids), orientation and in-circle exactly zero (a centroid exactly
// on the terminal edge, symmetric and cocircular sets), angles exactly at or next
// to a threshold (45 degrees against theta = 45, 90, near 0 and near 180), and
// hole points exactly on vertices, segments and unconstrained edges.
//
// Like gen.h: lattice coordinates times `scale` (exact predicates in double), and
// Pslg::source names the family. Unlike gen.h, some families are meant to make
// validate() warn (a hole point on a segment or a vertex removes nothing): run
// them through validate() before an engine sees them.
#pragma once
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

#include <rapidcheck.h>

#include "lepp/gen.h"
#include "lepp/pslg.h"

namespace lepp::gen {

/// Mirror-symmetric point sets: a box [-W, W] x [-H, H] (sides sampled every
/// `stride` lattice points) and up to 12 points of the quadrant x, y > 0 taken
/// with their images under a symmetry group: the mirror x -> -x, the mirror
/// y -> -y, both, or the half turn. Every mirrored pair of points makes equal
/// edge lengths (ties decided by ids) and every two pairs an isosceles trapezoid
/// (four cocircular points); a point pair mirrored across a terminal edge's line
/// puts the quad centroid exactly on that edge. "gen:mirror"
inline rc::Gen<Pslg> mirrorSymmetric(double scale = 1) {
  return rc::gen::apply(
      [scale](int w, int h, int stride, int group, const std::vector<std::pair<int, int>>& raw) {
        detail::Builder b;
        b.ring({{-w, -h}, {w, -h}, {w, h}, {-w, h}}, stride, 1);
        for (std::size_t i = 0; i < raw.size() && i < 12; ++i) {
          const std::int64_t x = 1 + raw[i].first % (w - 1), y = 1 + raw[i].second % (h - 1);
          std::vector<IPoint> orbit{{x, y}};
          if (group == 0 || group == 2) orbit.push_back({-x, y});
          if (group == 1 || group == 2) orbit.push_back({x, -y});
          if (group == 2 || group == 3) orbit.push_back({-x, -y});
          for (const IPoint& p : orbit)
            if (!b.occupied(p)) b.vertex(p);
        }
        return b.build("gen:mirror", scale);
      },
      rc::gen::inRange(3, 17), rc::gen::inRange(3, 17), rc::gen::inRange(0, 3), rc::gen::inRange(0, 4),
      rc::gen::container<std::vector<std::pair<int, int>>>(rc::gen::pair(rc::gen::inRange(0, 64), rc::gen::inRange(0, 64))));
}

/// Kites symmetric about their diagonal AB = (-a, 0)-(a, 0), apexes C = (c, h1)
/// and D = (c, -h2), as the boundary of the domain, with up to 3 interior points
/// on the axis y = 0 or x = c. With h1 = h2 (a mirror kite, every rhombus) the
/// centroid of the terminal quad lies exactly on AB (orientation zero: the
/// insertion splits the terminal edge); with c = 0 the sides tie in length. "gen:kite"
inline rc::Gen<Pslg> mirrorKite(double scale = 1) {
  return rc::gen::apply(
      [scale](int a, int c, int h1, int h2, bool equal, const std::vector<int>& inner) {
        const std::int64_t A = a, C = c % a, H1 = h1, H2 = equal ? h1 : h2;
        detail::Builder b;
        b.ring({{-A, 0}, {C, -H2}, {A, 0}, {C, H1}}, 1, 1);
        for (std::size_t i = 0; i < inner.size() && i < 3; ++i) {
          // On the diagonal AB or on the axis of symmetry x = C, strictly inside.
          const IPoint p = (inner[i] & 1) ? IPoint{-A + 1 + (inner[i] >> 1) % (2 * A - 1), 0}
                                          : IPoint{C, -std::min(H1, H2) + 1 + (inner[i] >> 1) % (2 * std::min(H1, H2) - 1)};
          if (!b.occupied(p)) b.vertex(p);
        }
        return b.build("gen:kite", scale);
      },
      rc::gen::inRange(2, 33), rc::gen::inRange(0, 33), rc::gen::inRange(1, 57), rc::gen::inRange(1, 57),
      rc::gen::arbitrary<bool>(), rc::gen::container<std::vector<int>>(rc::gen::inRange(0, 256)));
}

/// Hole points exactly where the domain rule (ALGORITHM.md section 2) decides
/// something: the box [0, 8k]^2 (k >= 2: the ring stays off the box) around an inner triangle ring P0 P1 P2 with a
/// vertex Q inside it (so the edges Q-Pi are unconstrained CDT edges), and one
/// hole point: strictly inside a triangle Q Pi Pj (removes the inside of the
/// ring), at the midpoint of Q-P0 (on an unconstrained edge: removes both
/// triangles, hence the ring's inside), at P1 or Q (on a vertex: removes
/// nothing), at the midpoint of P1-P2 (on a segment: removes nothing), or on the
/// outer boundary (removes nothing). "gen:hole-on"
inline rc::Gen<Pslg> holeOnBoundary(double scale = 1) {
  return rc::gen::apply(
      [scale](int k, int where, int jx, int jy) {
        const std::int64_t K = 4 * k;  // a multiple of 4: the midpoints below are lattice points
        detail::Builder b;
        b.ring({{0, 0}, {2 * K, 0}, {2 * K, 2 * K}, {0, 2 * K}}, 0, 1);
        const IPoint p0{K / 2, K / 2}, p1{K + K / 2, K / 2 + 2 * (jx % 2)}, p2{K, K + K / 2 + 2 * (jy % 2)};
        const IPoint q{K, K};  // strictly inside the ring for every jitter
        b.vertex(q);
        b.ring({p0, p1, p2}, 0, 2);
        IPoint hole;
        switch (where) {
          case 0: hole = {q.x, q.y - 1}; break;                                 // inside the triangle Q P0 P1 (or Q P1 P2)
          case 1: hole = {(q.x + p0.x) / 2, (q.y + p0.y) / 2}; break;           // on the unconstrained edge Q-P0
          case 2: hole = p1; break;                                             // on a ring vertex
          case 3: hole = q; break;                                              // on the free vertex
          case 4: hole = {(p1.x + p2.x) / 2, (p1.y + p2.y) / 2}; break;         // on the segment P1-P2 (lattice point)
          default: hole = {K, 0}; break;                                        // on the outer boundary
        }
        b.hole(hole);
        return b.build("gen:hole-on", scale);
      },
      rc::gen::inRange(2, 9), rc::gen::inRange(0, 6), rc::gen::inRange(0, 4), rc::gen::inRange(0, 4));
}

/// Input angles exactly at or next to the thresholds the algorithm compares:
/// a right isosceles corner (45 and 90 degrees exactly: theta = 45 is the one
/// integer theta a lattice angle can equal, and its sin^2 bracket rounds up, so
/// the 45-degree corner is skinny and a 45-degree input wedge unimprovable), a
/// sliver wedge of slope 1/L (near 0 degrees), a boundary bent by one lattice
/// unit (near 180 degrees, both convex and reflex), and an almost right corner
/// (90 degrees minus atan(1/L)). Each as a polygon, sides sampled every s. "gen:angles"
inline rc::Gen<Pslg> thresholdAngles(double scale = 1) {
  return rc::gen::apply(
      [scale](int kind, int len, int stride) {
        const std::int64_t L = len;
        std::vector<IPoint> ring;
        switch (kind) {
          case 0: ring = {{0, 0}, {L, 0}, {0, L}}; break;                          // 90, 45, 45
          case 1: ring = {{0, 0}, {L, 0}, {L, L}, {0, 2 * L}}; break;              // 90, 90, 135, 45
          case 2: ring = {{0, 0}, {L, 0}, {L, 1}}; break;                          // atan(1/L): near 0
          case 3: ring = {{0, 0}, {L, 1}, {2 * L, 0}, {2 * L, L}, {0, L}}; break;   // reflex bend by one unit (near 180)
          case 4: ring = {{0, 0}, {L, -1}, {2 * L, 0}, {2 * L, L}, {0, L}}; break;  // convex bend by one unit (near 180)
          default: ring = {{0, 0}, {L, 0}, {1, L}}; break;                         // 90 - atan(1/L) at the origin
        }
        detail::Builder b;
        b.ring(ring, stride, 1);
        return b.build("gen:angles", scale);
      },
      rc::gen::inRange(0, 6), rc::gen::inRange(4, 33), rc::gen::inRange(0, 3));
}

/// Any of the degenerate families above, or gen.h's near-degenerate ones (collinear
/// runs, lattice circles, grids, points close to a crack).
inline rc::Gen<Pslg> anyDegenerate(double scale = 1) {
  return rc::gen::oneOf(mirrorSymmetric(scale), mirrorKite(scale), holeOnBoundary(scale), thresholdAngles(scale),
                        nearDegenerate(scale));
}

/// The same PSLG with its vertices renumbered by a random permutation (segments
/// and holes follow): edge-length ties are decided by ids, so the decisions move.
inline rc::Gen<Pslg> withPermutedIds(rc::Gen<Pslg> pslgs) {
  return rc::gen::apply(
      [](const Pslg& p, const std::vector<std::uint32_t>& keys) {
        // Vertex indices sorted by (key, index): a permutation that shrinks toward the identity.
        std::vector<int> order(p.vertices.size());
        std::iota(order.begin(), order.end(), 0);
        auto key = [&](int i) { return static_cast<std::size_t>(i) < keys.size() ? keys[static_cast<std::size_t>(i)] : 0u; };
        std::stable_sort(order.begin(), order.end(), [&](int i, int j) { return key(i) < key(j); });
        std::vector<int> new_id(p.vertices.size());
        for (std::size_t k = 0; k < order.size(); ++k) new_id[static_cast<std::size_t>(order[k])] = static_cast<int>(k);
        Pslg q = p;
        for (std::size_t i = 0; i < p.vertices.size(); ++i) q.vertices[static_cast<std::size_t>(new_id[i])] = p.vertices[i];
        for (Segment& s : q.segments) s.a = new_id[static_cast<std::size_t>(s.a)], s.b = new_id[static_cast<std::size_t>(s.b)];
        return q;
      },
      std::move(pslgs), rc::gen::container<std::vector<std::uint32_t>>(rc::gen::inRange<std::uint32_t>(0, 64)));
}

}  // namespace lepp::gen
