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
#include <memory>

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
  }

 private:
  struct Index;
  void add_to_chain(const TriMesh& m, int segment, int v);

  const Pslg& pslg_;
  const SegmentMembership& mem_;
  std::unique_ptr<Index> index_;  // null until the first sliver test
  OutsideInput near_;             // the candidates of one test, reused
};

}  // namespace lepp::fast
