// Which triangles are bad, and which bad ones are left alone (ALGORITHM.md
// sections 4 and 8): skinny and too-big tests, and the unimprovable rule.
#pragma once
#include <cmath>
#include <utility>

#include "edge_order.h"
#include "lepp/refine.h"
#include "predicates.h"
#include "tri_mesh.h"

namespace lepp::fast {

class Quality {
 public:
  Quality(const Pslg& pslg, const SegmentMembership& membership, double sin2, double max_area)
      : pslg_(pslg), mem_(membership), s_(sin2), twice_area_(2 * max_area) {}

  struct Verdict {
    bool skinny = false, too_big = false;
    int shortest = 0;  // edge index
  };

  Verdict judge(const TriMesh& m, int ti) const {
    Verdict v;
    v.shortest = EdgeOrder(m, ti).rank().shortest;
    const FTri& f = m.t(ti);
    v.skinny = skinny_at(m.p(f.v[v.shortest]), m.p(f.v[next3(v.shortest)]), m.p(f.v[prev3(v.shortest)]), s_);
    v.too_big = twice_area_ > 0 && area_above(m.p(f.v[0]), m.p(f.v[1]), m.p(f.v[2]), twice_area_);
    return v;
  }

  // Bad, and not left alone by the unimprovable rule.
  bool processed(const TriMesh& m, int ti) const {
    Verdict v = judge(m, ti);
    if (v.too_big) return true;
    return v.skinny && !unimprovable(m, ti, v.shortest, nullptr);
  }

  // The rule of section 8 for a skinny triangle with shortest edge `shortest`;
  // fills *out with the smallest qualifying segment pair (s1 < s2).
  bool unimprovable(const TriMesh& m, int ti, int shortest, UnimprovableTriangle* out) const {
    const FTri& f = m.t(ti);
    const int p = f.v[next3(shortest)], q = f.v[prev3(shortest)];
    if (!mem_.on_any(p) || !mem_.on_any(q)) return false;
    bool found = false;
    int best1 = 0, best2 = 0, best_apex = -1;
    mem_.for_each(p, [&](int s1) {
      mem_.for_each(q, [&](int s2) {
        if (s1 == s2) return;
        int lo = std::min(s1, s2), hi = std::max(s1, s2);
        if (found && std::make_pair(lo, hi) >= std::make_pair(best1, best2)) return;
        int apex = small_angle_apex(s1, s2);
        if (apex < 0 || apex == p || apex == q) return;
        found = true, best1 = lo, best2 = hi, best_apex = apex;
      });
    });
    if (found && out) {
      *out = UnimprovableTriangle{};
      out->triangle = {f.v[0], f.v[1], f.v[2]};
      out->apex = best_apex, out->segment1 = best1, out->segment2 = best2;
      out->input_angle_deg = angle_deg(best_apex, best1, best2);
    }
    return found;
  }

 private:
  // The shared endpoint of segments s1, s2 if the angle between them there is below theta, else -1.
  int small_angle_apex(int s1, int s2) const {
    const Segment& a = pslg_.segments[static_cast<std::size_t>(s1)];
    const Segment& b = pslg_.segments[static_cast<std::size_t>(s2)];
    int v, oa, ob;
    if (a.a == b.a) v = a.a, oa = a.b, ob = b.b;
    else if (a.a == b.b) v = a.a, oa = a.b, ob = b.a;
    else if (a.b == b.a) v = a.b, oa = a.a, ob = b.b;
    else if (a.b == b.b) v = a.b, oa = a.a, ob = b.a;
    else return -1;
    const Point &pv = pt(v), &pa = pt(oa), &pb = pt(ob);
    return dot_sign(pv, pa, pb) > 0 && skinny_at(pv, pa, pb, s_) ? v : -1;
  }
  double angle_deg(int apex, int s1, int s2) const {
    auto other = [&](int s) {
      const Segment& g = pslg_.segments[static_cast<std::size_t>(s)];
      return pt(g.a == apex ? g.b : g.a);
    };
    const Point &v = pt(apex), a = other(s1), b = other(s2);
    double ux = a.x - v.x, uy = a.y - v.y, wx = b.x - v.x, wy = b.y - v.y;
    return std::atan2(std::fabs(ux * wy - uy * wx), ux * wx + uy * wy) * 180.0 / M_PI;
  }
  const Point& pt(int v) const { return pslg_.vertices[static_cast<std::size_t>(v)]; }

  const Pslg& pslg_;
  const SegmentMembership& mem_;
  double s_, twice_area_;
};

}  // namespace lepp::fast
