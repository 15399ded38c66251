// SPDX-License-Identifier: GPL-3.0-or-later
// What can block a sliver split (ALGORITHM.md section 8b, the sliver clause): a
// boundary split whose rounded midpoint p falls strictly outside the domain also
// covers the closed thin triangle a, p, b, and every input vertex and every
// constrained edge is tested against it, the domain's own boundary included (as
// the reference's scan of its whole triangulation). Rather than a scan, a static
// R-tree of the input segments' and lone vertices' bounding boxes finds the few
// near the triangle, and each segment's chain (its vertices in order along it)
// gives the constrained edges on it there. Built on the first sliver test, so
// runs that never reach the clause pay nothing; from then on each segment split
// keeps its chain.
#pragma once
#include <map>
#include <memory>
#include <tuple>

#include "lepp/boundary_sliver.h"
#include "lepp/pslg.h"
#include "tri_mesh.h"

namespace lepp::fast {

class SliverObstacles {
 public:
  SliverObstacles(const Pslg& pslg, const SegmentMembership& membership);
  ~SliverObstacles();

  // The sliver clause: the closed triangle a, p, b (vertices a, b of m; p strictly
  // right of a -> b, ab a domain boundary edge) holds a vertex other than a, b, or a
  // constrained edge other than ab meets it (lepp::sliver_blocked's tests). A domain vertex on no
  // segment needs no test: were it in the triangle, the domain around it would
  // reach the triangle's outside part near ab through a boundary edge, which
  // then meets the triangle.
  bool blocks(const TriMesh& m, int a, int b, const Point& p);

  // Steiner vertex v, just inserted, split a constrained edge of `segment`.
  void on_split(const TriMesh& m, int segment, int v) {
    if (index_) add_to_chain(m, segment, v);
    answers_.clear();  // a chain changed: earlier answers may not hold
  }

 private:
  struct Index;
  void add_to_chain(const TriMesh& m, int segment, int v);
  bool test(const TriMesh& m, int a, int b, const Point& p);  // blocks, not remembered

  const Pslg& pslg_;
  const SegmentMembership& mem_;
  std::unique_ptr<Index> index_;  // null until the first sliver test
  OutsideInput near_;             // the candidates of one test, reused
  // The answers since the last split, by (a, b, p): blocks reads only the input, the
  // chains and the vertices' points, which no other insertion changes. The precision
  // limit's tie search asks the same slivers again and again (fuzz_differential's
  // slowest input: 13,804 tests, 4,189 of them new, each about 1,500 exact
  // orientations against an ulp cluster).
  std::map<std::tuple<int, int, double, double>, bool> answers_;
};

}  // namespace lepp::fast
