// SPDX-License-Identifier: GPL-3.0-or-later
// Private to the conformance replay: the cocircular cells of a constrained Delaunay mesh
// and the triangles their retriangulations make. A cell is a maximal set of
// domain triangles joined by unconstrained edges whose quads are exactly
// cocircular: a convex polygon inscribed in one empty circle. Every
// triangulation of every cell, chosen independently, is a constrained
// Delaunay triangulation of the same points and segments, and every one of
// them is obtained so: the cells are the constrained Delaunay mesh's only
// freedom (docs/CONFORMANCE.md, "Cocircular cells").
#pragma once
#include <array>
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

#include "triangulation.h"  // reference/src: the exact engine's CDT (lepp_reference_internals)

namespace lepp::audit::replay_detail {

// The replay works on the reference engine's triangulation and insertion.
using namespace lepp::reference::detail;

bool in_domain(const Triangulation& tr, FH f);
// An unconstrained edge between two domain triangles whose four points are
// exactly cocircular: either diagonal is constrained Delaunay.
bool cocircular_edge(const Triangulation& tr, FH f, int i);

struct Cell {
  std::vector<VH> ring;               // the polygon, counter-clockwise (3 vertices: one triangle, no freedom)
  std::vector<char> side_constrained;  // side k: ring[k] -> ring[k + 1]
  std::vector<FH> side_outside;        // a domain face across side k; null when constrained or outside the domain
  int region = 0;                      // FaceInfo::region of its faces (joined by unconstrained edges: one region)
  int position(VH v) const;            // index in ring, -1 if none
};

// A triangle some triangulation of a cell has: three ring positions, CCW.
struct CellTri {
  int cell = -1;
  std::array<int, 3> pos{{-1, -1, -1}};
  std::array<VH, 3> v;
  std::array<bool, 3> constrained{{false, false, false}};  // edge i, opposite v[i]
  int region = 0;                      // its cell's region (for the size bound)
};

// The cells of the current mesh, found on demand. Flips inside cells keep it
// valid (a flip changes neither a cell's polygon nor which cell a face is in);
// an insertion does not.
class CellMap {
 public:
  explicit CellMap(const Triangulation& tr) : tr_(tr) {}
  int cell_of(FH f);
  const Cell& cell(int c) const { return cells_[static_cast<std::size_t>(c)]; }
  // The triangle with ring positions a, b, d (counter-clockwise) of cell c.
  CellTri triangle(int c, int a, int b, int d) const;
  // Appends the triangles across edge i of t that some triangulation puts
  // there: in t's cell across a diagonal, in the cell across a side; none
  // across a constrained edge or the domain's boundary.
  void across(const CellTri& t, int i, std::vector<CellTri>& out);
  // Two distinct triangles of one cell overlap (no triangulation has both).
  bool overlap(const CellTri& a, const CellTri& b) const;

 private:
  const Triangulation& tr_;
  std::vector<Cell> cells_;
  std::map<FH, int> cell_of_;
};

using EdgeIds = std::pair<int, int>;
// Flips cocircular diagonals until each triangle of `want` (pairwise not
// overlapping) is a face of the mesh; appends every flip (the edge it made) to
// `flips`. Every flip is inside a cell, so the mesh stays constrained
// Delaunay. false if some triangle could not be made (the flips stay logged).
bool realize(Triangulation& tr, const CellMap& cells, const std::vector<CellTri>& want, std::vector<EdgeIds>& flips);
// Reverses the logged flips, last first.
void undo_flips(Triangulation& tr, std::vector<EdgeIds>& flips);

}  // namespace lepp::audit::replay_detail
