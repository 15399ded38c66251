// SPDX-License-Identifier: GPL-3.0-or-later
// The small-input-angle exemption rule on the mesh (docs/CERTIFIER.md): which small input angle exempts a triangle.
#include "small_angle_exemption.h"

#include <cmath>

#include "../exact.h"

namespace lepp::certify {
namespace {

// Mesh vertex p is on segment s of angle a ("an arm"): s's other endpoint, or a vertex
// of s's chain (the apex itself excluded).
bool on_arm(const MeshIndex& ix, int p, int s, int end) {
  const int in = ix.mesh_to_input[static_cast<std::size_t>(p)];
  if (in >= 0) return in == end;
  return ix.vertex_segment[static_cast<std::size_t>(p)] == s;
}
// |p - apex| <= R (the shorter segment's length), exactly.
bool in_disk(const MeshIndex& ix, int p, const SmallInputAngle& a) {
  const Point& V = ix.pslg.vertices[static_cast<std::size_t>(a.apex)];
  const Point& X = ix.P(p);
  if (std::abs(X.x - V.x) > 2 * a.radius || std::abs(X.y - V.y) > 2 * a.radius) return false;  // far: cheap
  return exact::compare_squared_length(V, X, V, ix.pslg.vertices[static_cast<std::size_t>(a.near_end)]) <= 0;
}
// Triangle pqr, pq joining the two arms of a, lies in the wedge: r is on an arm (or is
// the apex), or in the closed sector from segment1 counter-clockwise to segment2 (exact).
bool inside_wedge(const MeshIndex& ix, int r, const SmallInputAngle& a) {
  if (on_arm(ix, r, a.segment1, a.end1) || on_arm(ix, r, a.segment2, a.end2)) return true;
  const Point& V = ix.pslg.vertices[static_cast<std::size_t>(a.apex)];
  const Point &E1 = ix.pslg.vertices[static_cast<std::size_t>(a.end1)], &E2 = ix.pslg.vertices[static_cast<std::size_t>(a.end2)];
  return exact::orient(V, E1, ix.P(r)) >= 0 && exact::orient(V, ix.P(r), E2) >= 0;
}

}  // namespace

// The first small input angle (Report::small_angles order) that exempts triangle t, or -1.
// Every shortest edge is tried (exact ties kept), so the answer does not depend on the
// mesh's vertex numbering. Exempt iff, for some angle a and some shortest edge pq:
//  span: p is on one arm of a and q on the other (the edge crosses the wedge) and the
//        triangle lies in the wedge (its third vertex on an arm or in the sector), or
//  near: p and q lie in the disk of a (within the shorter segment's length of the apex).
int exempting_angle(const MeshIndex& ix, const std::vector<SmallInputAngle>& angles, std::size_t t) {
  const Tri& x = ix.T(t);
  std::array<std::array<int, 3>, 3> shortest{};  // p, q, and the third vertex
  int count = 0;
  for (int i = 0; i < 3; ++i) {
    const int p = x[static_cast<std::size_t>(i)], q = x[static_cast<std::size_t>((i + 1) % 3)];
    bool is_shortest = true;
    for (int j = 0; j < 3 && is_shortest; ++j)
      if (j != i)
        is_shortest = exact::compare_squared_length(ix.P(p), ix.P(q), ix.P(x[static_cast<std::size_t>(j)]),
                                                    ix.P(x[static_cast<std::size_t>((j + 1) % 3)])) <= 0;
    if (is_shortest) shortest[static_cast<std::size_t>(count++)] = {p, q, x[static_cast<std::size_t>((i + 2) % 3)]};
  }
  for (std::size_t k = 0; k < angles.size(); ++k) {
    const SmallInputAngle& a = angles[k];
    for (int e = 0; e < count; ++e) {
      const int p = shortest[static_cast<std::size_t>(e)][0], q = shortest[static_cast<std::size_t>(e)][1];
      const int r = shortest[static_cast<std::size_t>(e)][2];
      const bool span = (on_arm(ix, p, a.segment1, a.end1) && on_arm(ix, q, a.segment2, a.end2)) ||
                        (on_arm(ix, p, a.segment2, a.end2) && on_arm(ix, q, a.segment1, a.end1));
      if (span && inside_wedge(ix, r, a)) return static_cast<int>(k);
      if (in_disk(ix, p, a) && in_disk(ix, q, a)) return static_cast<int>(k);
    }
  }
  return -1;
}

}  // namespace lepp::certify
