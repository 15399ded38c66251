// SPDX-License-Identifier: GPL-3.0-or-later
// The flips of a program that makes its own Lawson flips (docs/CONFORMANCE.md
// "The program's mesh"): after a point is inserted, flips around it, never across
// a constrained edge, each decided by the in-circle determinant as the program
// evaluates it. DoubleIncircle: in double; where that disagrees with the exact
// sign (a quad cocircular within rounding), the replay's mesh is the program's,
// not the constrained Delaunay one. TiesKept: exactly, flipped only strictly
// inside, so an exactly cocircular quad keeps its diagonal, where CGAL's
// insertion breaks the tie by its symbolic perturbation.
#include <algorithm>
#include <array>
#include <vector>

#include "replayer.h"

namespace lepp::audit::replay_detail {

namespace {

// The in-circle determinant in double, Shewchuk's translated form (differences to
// d), positive when d lies strictly inside the circle through a, b, c
// (counter-clockwise). The triangle is taken from its smallest vertex in (x, y)
// order, so that the rounding does not depend on how a mesh numbers its corners.
double incircle_double(std::array<Point, 3> t, const Point& d) {
  auto smaller = [](const Point& u, const Point& v) { return u.x < v.x || (u.x == v.x && u.y < v.y); };
  std::rotate(t.begin(), std::min_element(t.begin(), t.end(), smaller), t.end());
  const double adx = t[0].x - d.x, ady = t[0].y - d.y, bdx = t[1].x - d.x, bdy = t[1].y - d.y, cdx = t[2].x - d.x,
               cdy = t[2].y - d.y;
  const double alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy, clift = cdx * cdx + cdy * cdy;
  return alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) + clift * (adx * bdy - bdx * ady);
}

Point as_double(VH v) { return {CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y())}; }

}  // namespace

// The reference's legalization order (restore_delaunay): the faces around v,
// each legalized depth first; only the decision differs.
void Replayer::program_lawson(VH v) {
  const bool in_double = rules.mesh == MeshReading::DoubleIncircle;
  std::vector<FH> stack;
  Cdt::Face_circulator fc = tr.cdt.incident_faces(v), done = fc;
  do stack.push_back(fc); while (++fc != done);
  std::reverse(stack.begin(), stack.end());
  const Point d = as_double(v);
  while (!stack.empty()) {
    FH f = stack.back();
    stack.pop_back();
    const int i = f->index(v);
    FH n = f->neighbor(i);
    if (f->is_constrained(i) || tr.cdt.is_infinite(f) || tr.cdt.is_infinite(n)) continue;
    if (in_double) {
      const std::array<Point, 3> t{as_double(n->vertex(0)), as_double(n->vertex(1)), as_double(n->vertex(2))};
      if (!(incircle_double(t, d) > 0)) continue;
    } else if (CGAL::side_of_oriented_circle(n->vertex(0)->point(), n->vertex(1)->point(), n->vertex(2)->point(),
                                             v->point()) != CGAL::ON_POSITIVE_SIDE) {
      continue;
    }
    // A flip the double decides but the quad does not allow (not strictly convex)
    // would make a flat or folded triangle: no program's mesh has it.
    const CPoint& a = f->vertex(Cdt::ccw(i))->point();
    const CPoint& b = f->vertex(Cdt::cw(i))->point();
    const CPoint& o = n->vertex(n->index(f))->point();
    if (CGAL::orientation(v->point(), a, o) != CGAL::LEFT_TURN || CGAL::orientation(v->point(), o, b) != CGAL::LEFT_TURN)
      continue;
    tr.cdt.flip(f, i);
    stack.push_back(n);
    stack.push_back(f);
  }
}

}  // namespace lepp::audit::replay_detail
