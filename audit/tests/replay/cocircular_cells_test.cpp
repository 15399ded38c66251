// SPDX-License-Identifier: GPL-3.0-or-later
// The replay's cocircular cells, white-box (audit/src/replay/cocircular_cells.h):
// on an octagon inscribed in one circle, the cell's ring, the overlap test of
// two of its triangles (crossing chords, the same triangle named twice, a
// shared side), the triangles across a diagonal, across a segment (none) and
// across an unconstrained side into the next cell, and cocircular_edge on the
// faces outside the domain. The replay's search uses each of these; the tests
// through it (conformance_cocircular_test.cpp) never needed two crossing
// triangles of one cell or a path leaving its cell across a segment.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "../../src/replay/cocircular_cells.h"
#include "lepp/validate.h"

namespace lepp::audit::replay_detail {
namespace {

// The eight lattice points at distance sqrt(10) from the origin, counter-clockwise
// from (3, -1); with `notch`, the side (3,-1)-(3,1) bulges out to (5, 0), a
// vertex off the circle: that side is then an unconstrained edge to a face of another cell.
Pslg octagon(bool notch) {
  Pslg p;
  p.vertices = {{3, -1}, {3, 1}, {1, 3}, {-1, 3}, {-3, 1}, {-3, -1}, {-1, -3}, {1, -3}};
  if (notch) p.vertices.push_back({5, 0});
  const int n = 8;
  for (int i = 0; i < n; ++i) {
    if (notch && i == 0) {
      p.segments.push_back({0, 8, 0});
      p.segments.push_back({8, 1, 0});
      continue;
    }
    p.segments.push_back({i, (i + 1) % n, 0});
  }
  std::vector<std::string> warnings;
  return validate(p, warnings);
}

struct Built {
  Pslg pslg;
  Triangulation tr;
  explicit Built(bool notch) : pslg(octagon(notch)) { build_triangulation(pslg, tr); }
  FH face_with(int a, int b) const {
    FH f;
    int i;
    EXPECT_TRUE(tr.cdt.is_edge(tr.vertex[static_cast<std::size_t>(a)], tr.vertex[static_cast<std::size_t>(b)], f, i));
    return in_domain(tr, f) ? f : f->neighbor(i);
  }
};

TEST(CocircularCells, OctagonIsOneCell) {
  Built b(false);
  CellMap cells(b.tr);
  int c = -1;
  std::size_t domain_faces = 0;
  for (FH f : b.tr.cdt.finite_face_handles()) {
    if (!in_domain(b.tr, f)) continue;
    ++domain_faces;
    const int here = cells.cell_of(f);
    if (c < 0) c = here;
    EXPECT_EQ(here, c) << "every face of the octagon is in its one cell";
  }
  EXPECT_EQ(domain_faces, 6u);
  const Cell& cell = cells.cell(c);
  ASSERT_EQ(cell.ring.size(), 8u);
  EXPECT_EQ(std::count(cell.side_constrained.begin(), cell.side_constrained.end(), 1), 8);
  // A vertex of the ring has its position; one that is not (a bounding box corner) has none.
  for (std::size_t k = 0; k < 8; ++k) EXPECT_EQ(cell.position(cell.ring[k]), static_cast<int>(k));
  VH corner;
  for (VH v : b.tr.cdt.finite_vertex_handles())
    if (v->info().id < 0) corner = v;
  ASSERT_NE(corner, VH());
  EXPECT_EQ(cell.position(corner), -1);
}

TEST(CocircularCells, OverlapOfTwoTrianglesOfTheCell) {
  Built b(false);
  CellMap cells(b.tr);
  const int c = cells.cell_of(b.face_with(0, 1));
  // Crossing chords: 0-2-4 and 1-3-5 (0-2 crosses 1-3).
  EXPECT_TRUE(cells.overlap(cells.triangle(c, 0, 2, 4), cells.triangle(c, 1, 3, 5)));
  // The same triangle named from another corner.
  EXPECT_TRUE(cells.overlap(cells.triangle(c, 0, 2, 4), cells.triangle(c, 2, 4, 0)));
  // Two triangles of one triangulation (a fan from 0): sharing the chord 0-2, no overlap.
  EXPECT_FALSE(cells.overlap(cells.triangle(c, 0, 1, 2), cells.triangle(c, 0, 2, 3)));
  // Sharing only the vertex 0, on either side: no overlap.
  EXPECT_FALSE(cells.overlap(cells.triangle(c, 0, 1, 2), cells.triangle(c, 0, 5, 6)));
  // 0-3-5 and 1-2-4: the chord 3-5 separates 4 from 1 and 2, 0-3 crosses 1-2? no; 2-4 crosses 3-5 and 0-3.
  EXPECT_TRUE(cells.overlap(cells.triangle(c, 0, 3, 5), cells.triangle(c, 1, 2, 4)));
  // Triangles of different cells never overlap.
  Built nb(true);
  CellMap other(nb.tr);
  const int c0 = other.cell_of(nb.face_with(0, 8)), c1 = other.cell_of(nb.face_with(2, 3));
  ASSERT_NE(c0, c1);
  const CellTri t0 = other.triangle(c0, 0, 1, 2);
  EXPECT_FALSE(other.overlap(t0, other.triangle(c1, 0, 1, 2)));
}

TEST(CocircularCells, TrianglesAcrossAnEdge) {
  Built b(false);
  CellMap cells(b.tr);
  const int c = cells.cell_of(b.face_with(0, 1));
  std::vector<CellTri> out;
  // Across the diagonal 0-4 of triangle 0-2-4 (edge opposite position 2... index 1 is opposite v[1]):
  // every ring vertex strictly between 4 and 0 counter-clockwise: 5, 6, 7.
  const CellTri t = cells.triangle(c, 0, 2, 4);
  cells.across(t, 1, out);  // edge 1 runs from pos[2]=4 to pos[0]=0
  std::set<int> apexes;
  for (const CellTri& u : out) {
    EXPECT_EQ(u.cell, c);
    apexes.insert(u.pos[2]);
  }
  EXPECT_EQ(apexes, (std::set<int>{5, 6, 7}));
  // Across a side that is a segment: nothing (a Lepp stops at a constrained edge).
  out.clear();
  const CellTri s = cells.triangle(c, 0, 1, 2);
  cells.across(s, 2, out);  // edge 2 runs from pos[0]=0 to pos[1]=1: the segment 0-1
  EXPECT_TRUE(s.constrained[2]);
  EXPECT_TRUE(out.empty());
}

TEST(CocircularCells, AcrossAnUnconstrainedSideIntoTheNextCell) {
  Built b(true);
  CellMap cells(b.tr);
  const int c = cells.cell_of(b.face_with(2, 3));
  const Cell& cell = cells.cell(c);
  ASSERT_EQ(cell.ring.size(), 8u);
  // The side 0 -> 1 (input ids) is no segment now: the notch's triangle 0-8-1 is across it.
  const int p0 = cell.position(b.tr.vertex[0]), p1 = cell.position(b.tr.vertex[1]);
  ASSERT_GE(p0, 0);
  ASSERT_EQ((p0 + 1) % 8, p1);
  EXPECT_FALSE(cell.side_constrained[static_cast<std::size_t>(p0)]);
  ASSERT_NE(cell.side_outside[static_cast<std::size_t>(p0)], FH());
  const CellTri t = cells.triangle(c, p0, p1, (p1 + 1) % 8);
  std::vector<CellTri> out;
  cells.across(t, 2, out);  // edge 2: pos[0] -> pos[1], the side 0-1
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NE(out[0].cell, c);
  std::set<int> ids;
  for (VH v : out[0].v) ids.insert(v->info().id);
  EXPECT_EQ(ids, (std::set<int>{0, 1, 8}));
}

TEST(CocircularCells, NoCocircularEdgeOutsideTheDomain) {
  Built b(false);
  std::size_t cocircular = 0, outside_faces = 0;
  for (FH f : b.tr.cdt.all_face_handles()) {
    if (b.tr.cdt.is_infinite(f)) continue;
    if (!in_domain(b.tr, f)) ++outside_faces;
    for (int i = 0; i < 3; ++i)
      if (cocircular_edge(b.tr, f, i)) {
        ++cocircular;
        EXPECT_TRUE(in_domain(b.tr, f));
        EXPECT_FALSE(f->is_constrained(i));
      }
  }
  EXPECT_GT(outside_faces, 0u);
  EXPECT_EQ(cocircular, 10u) << "5 diagonals of the octagon's 6 triangles, each seen from both sides";
}

}  // namespace
}  // namespace lepp::audit::replay_detail
