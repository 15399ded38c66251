// SPDX-License-Identifier: GPL-3.0-or-later
// Private to the reference engine (and the replay built on it through
// lepp_reference_internals): the CGAL types and the bookkeeping around them.
// CGAL stays out of every public header; reference.h speaks plain doubles.
#pragma once
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <cstdint>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "lepp/mesh.h"
#include "lepp/pslg.h"
#include "lepp/refine.h"
#include "longest_edge_memo.h"

namespace lepp::reference::detail {

using K = CGAL::Exact_predicates_exact_constructions_kernel;  // Epeck: every decision is exact
using FT = K::FT;
using CPoint = K::Point_2;

// id: 0..n-1 input vertices, n.. Steiner points in insertion order, -1 the
// four bounding-box corners (never part of the domain, never output).
// segments: the input segments the vertex lies on (ALGORITHM.md, Section 1).
struct VertexInfo {
  int id = -1;
  std::vector<int> segments;
};
struct FaceInfo {
  bool in_domain = false;
  int region = 0;  // with region area bounds: 0 none, k + 1 the PSLG's region k
  // The audit's replay keeps facts of the faces it walks (audit/src/replay/face_facts.h)
  // and this is where a face's are (0: none; copied with the rest, checked there).
  // The engine never reads it; the face stays 64 bytes.
  std::uint32_t facts = 0;
};

using Vb = CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, K>;
using Fb = CGAL::Triangulation_face_base_with_info_2<FaceInfo, K, CGAL::Constrained_triangulation_face_base_2<K>>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
// Points on a constraint are allowed (the split of a constrained edge); crossings never happen.
using Itag = CGAL::No_constraint_intersection_requiring_constructions_tag;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, Itag>;
using VH = Cdt::Vertex_handle;
using FH = Cdt::Face_handle;

// The CDT and what the algorithm keeps beside it.
struct Triangulation {
  const Pslg* input = nullptr;
  Cdt cdt;
  std::vector<VH> vertex;     // by id
  std::vector<Point> coords;  // the double coordinates, by id (exactly the CGAL points)
  std::size_t input_vertices = 0;
  // Constrained edge (smaller id, larger id) -> the input segment it lies on.
  std::map<std::pair<int, int>, int> segment_of_edge;
  std::int64_t cocircular_ties = 0;
};

// The key of an edge in segment_of_edge (by value: std::minmax of temporaries dangles).
inline std::pair<int, int> edge_key(int a, int b) { return a < b ? std::make_pair(a, b) : std::make_pair(b, a); }

// --- cdt_build.cpp ---
// CDT of a validated PSLG inside a far bounding box (so that no input segment
// is ever on the convex hull), domain flags set by Triangle's -p flood.
void build_triangulation(const Pslg& pslg, Triangulation& tr);
// Region of every domain face (FaceInfo::region): each region point, in file
// order, floods the domain faces around it without crossing a constrained edge,
// overwriting earlier regions (Triangle's order). A point outside the domain, on
// a constrained edge or on a vertex sets nothing.
void assign_regions(Triangulation& tr);
// Domain triangles (CCW), input then Steiner vertices, tagged constrained edges; canonical.
Mesh extract_mesh(const Triangulation& tr);
// Unconstrained domain edges whose two triangles are cocircular.
std::int64_t count_cocircular_edges(const Triangulation& tr);

// --- geometry.cpp: exact decisions of ALGORITHM.md Sections 3, 4, 8 ---
inline int id(VH v) { return v->info().id; }
// The edge of f opposite vertex i, compared in the edge order of Section 3.
// Returns true iff edge (f,i) is strictly greater than edge (g,j).
bool edge_greater(FH f, int i, FH g, int j);
int longest_edge(FH f);         // index of the vertex opposite the longest edge
int second_longest_edge(FH f);
int shortest_edge(FH f);
// Every resolution of exact length ties (ALGORITHM.md section 8b, "Every tie resolution"):
// the edges of f of maximal exact length, the edge order's longest first; and the
// second-longest edges of f with edge e taken as its longest, the longer of the other
// two in the edge order first, both when their lengths tie.
std::vector<int> tied_longest_edges(FH f);
std::vector<int> tied_second_edges(FH f, int e);
Tri key(FH f);                  // ids sorted ascending
Tri ccw_ids(FH f);              // ids CCW, rotated to start at the smallest
bool is_skinny(FH f, const FT& sin2);
bool is_too_big(FH f, const FT& twice_max_area);
std::optional<UnimprovableTriangle> unimprovable(const Triangulation& tr, FH f, const FT& sin2);

struct Lepp {
  std::vector<FH> path;  // t first, then t1, then t2 if any
  FH t1, t2;             // t2 null for a constrained terminal edge
  int edge = -1;         // terminal edge as index in t1
  // The second-longest edges of t1 and t2 where another resolution of an exact
  // length tie fixed them (the precision limit, tie_resolutions.cpp); -1: the edge order's.
  int s1 = -1, s2 = -1;
};
// memo: if not null, longest edges are looked up and kept there (the Lepps of a
// refinement walk the same fans again and again).
Lepp find_lepp(FH t, LongestEdgeMemo* memo = nullptr);
// The second-longest edge of t1 (t2 when second) of the Lepp's terminal pair.
inline int second_longest_of(const Lepp& lepp, bool second) {
  const int fixed = second ? lepp.s2 : lepp.s1;
  return fixed >= 0 ? fixed : second_longest_edge(second ? lepp.t2 : lepp.t1);
}

// --- select_point.cpp: ALGORITHM.md Sections 5 and 6 ---
struct Selection {
  Rule rule = Rule::QuadCentroid;
  Point point;
  // A midpoint of a constrained edge: the edge (face, index) it splits.
  FH split_face;
  int split_index = -1;
};
Selection select_point(const Lepp& lepp, Method method);
// The precision stop (ALGORITHM.md section 8b): can the selected point, as rounded,
// be inserted where its insertion needs it (split: every new face counter-clockwise;
// otherwise in the closed terminal pair, off its vertices and constrained edges)?
bool insertable(const Triangulation& tr, const Selection& s, const Lepp& lepp);
// When it cannot: the doubles around the exact point (each coordinate rounded down
// and up), ascending x then y; the first insertable one (for centroid-in-other,
// still strictly inside the other triangle) replaces s.point. False: none is.
bool round_otherwise(const Triangulation& tr, const Lepp& lepp, Selection& s);
// Remark 10 at the limit, when that fails too: the other branch, if a double
// around the exact centroid turns the branch (one outside the other triangle:
// the midpoint of l*, as rounded; else those strictly inside it: the centroid).
bool other_branch(const Triangulation& tr, const Lepp& lepp, Method method, Selection& s);
// Both second-longest edges constrained, when t1's midpoint cannot be inserted at any
// rounding: t2's, the formula's double then its other roundings (the paper allows either
// constrained edge). False: t2's cannot either, or the rule is another.
bool other_constrained_edge(const Triangulation& tr, const Lepp& lepp, Selection& s);
// The selection s for this Lepp as the engine inserts it (section 8b, in this order):
// the formula's double, its other roundings, Remark 10's other branch, the other
// constrained second-longest edge. True iff one can be inserted (s then holds it).
inline bool settle_selection(const Triangulation& tr, const Lepp& lepp, Method method, Selection& s) {
  return insertable(tr, s, lepp) || round_otherwise(tr, lepp, s) || other_branch(tr, lepp, method, s) ||
         other_constrained_edge(tr, lepp, s);
}
// --- tie_resolutions.cpp ---
// When the edge order's Lepp of bad face t has no insertable selection: every Lepp of
// t and every second-longest edge under exact ties, depth first in the edge order,
// each settled as settle_selection says. True iff one can be inserted (lepp and s
// then hold it); else both unchanged. At most max_states Lepp states
// (RefineOptions::tie_search_states; 0: no bound).
// *cut (when given): when nothing is found, whether the bound left some state unseen.
bool other_tie_resolution(const Triangulation& tr, FH t, Method method, std::size_t max_states, Lepp& lepp, Selection& s,
                          bool* cut = nullptr);
// Inserts the selected point, restores the constrained Delaunay property by
// flips in the legalization order of ALGORITHM.md section 7 (counting cocircular
// ties), sets ids, segment membership and domain flags.
// created: if not null, set to the domain triangles the insertion made, in creation
// order (ALGORITHM.md section 7), as keys; some no longer exist at the end.
// kept: if not null, set to the triangle a split off its line kept beside its
// sliver (ALGORITHM.md section 6), else to null.
VH insert_point(Triangulation& tr, const Selection& s, FH t1, std::vector<Tri>* created = nullptr, FH* kept = nullptr);

}  // namespace lepp::reference::detail
