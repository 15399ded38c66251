// SPDX-License-Identifier: GPL-3.0-or-later
// One certification under way: the mesh index every pass reads, and the report they fill.
// Private to the certifier; CGAL stays out (exact.h is for the .cpp files).
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <unordered_map>
#include <vector>

#include <fmt/format.h>

#include "expected_domain.h"
#include "lepp/boundary_sliver.h"
#include "lepp/certify.h"
#include "unwritten.h"

namespace lepp::certify {

// An undirected edge as one number (smaller id in the high half).
inline std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}
// The ends of edge_key's edge (smaller id first).
inline std::array<int, 2> edge_ends(std::uint64_t key) {
  return {static_cast<int>(key >> 32), static_cast<int>(key & 0xffffffffu)};
}

// A point as the messages print it.
inline std::string pt(const Point& p) { return fmt::format("({}, {})", p.x, p.y); }

inline bool finite(const Point& p) { return std::isfinite(p.x) && std::isfinite(p.y); }

struct PointHash {
  std::size_t operator()(const Point& p) const {
    // Hashed by value, as Point's == compares: -0 and +0 are one point (adding +0.0
    // turns -0.0 into +0.0), so a mesher that prints -0 as 0 keeps its input vertex.
    const double px = p.x + 0.0, py = p.y + 0.0;
    std::uint64_t x = 0, y = 0;
    std::memcpy(&x, &px, sizeof x);
    std::memcpy(&y, &py, sizeof y);
    return std::hash<std::uint64_t>()(x * 0x9E3779B97F4A7C15ull ^ y);
  }
};

// What the passes share about the mesh, built once (index/*.cpp) and then only read.
struct MeshIndex {
  MeshIndex(const Pslg& p, const Mesh& m) : pslg(p), mesh(m) {}
  const Pslg& pslg;
  const Mesh& mesh;
  ExpectedDomain domain;
  OutsideInput outside;                          // the input outside the domain (index_domain)
  std::vector<std::array<int, 2>> chain_edges;   // chain_edge's edges sorted by key (index_chains), and
  std::vector<int> chain_edge_segment;           // the segment of each
  OutsideInput chain_segments;                   // the same edges as segments (the exemption's sliver clause)

  std::vector<char> tri_ok;            // ids valid (orientation may still be wrong)
  std::vector<char> ccw;               // valid and strictly counter-clockwise (index_triangles)
  UnwrittenVector<int> twin;           // half-edge 3t+i (t[i] -> t[i+1]): opposite half, -1 boundary, -2 bad edge
  std::size_t edge_count = 0;          // unique edges of valid triangles (the groups of halves)
  std::vector<char> used;              // in a valid triangle (index_adjacency: an end of an edge of one)
  // The half-edges of valid triangles by edge (index_half_edges): the ones whose smaller
  // end is v at [half_begin[v], half_begin[v + 1]) of halves, by larger end, then by id.
  struct Half {
    Half() {}  // not zeroed: vector::resize leaves the slots to the pass that fills them all
    Half(int larger_end, int half, bool from_smaller)
        : other(larger_end), code(2 * static_cast<std::uint32_t>(half) + (from_smaller ? 1 : 0)) {}
    int other;           // the larger end
    std::uint32_t code;  // 2 h + 1 if half-edge h runs from the smaller end to the larger, 2 h if back
    int h() const { return static_cast<int>(code >> 1); }
    bool up() const { return (code & 1) != 0; }  // runs from the smaller end: without loading its triangle
  };
  std::vector<int> half_begin;
  std::vector<Half> halves;
  // The edges from v to its larger neighbours, ascending: f(b, k) on the first half-edge
  // k of each group of halves in v's bucket (the edges are not stored apart).
  template <class F>
  void each_edge_up_from(std::size_t v, F&& f) const {
    for (std::size_t k = static_cast<std::size_t>(half_begin[v]); k < static_cast<std::size_t>(half_begin[v + 1]); ++k)
      if (k == static_cast<std::size_t>(half_begin[v]) || halves[k].other != halves[k - 1].other) f(halves[k].other, k);
  }
  // Each unique edge (a < b) of valid triangles, in key order: f(a, b, k), k as above.
  template <class F>
  void each_edge(F&& f) const {
    for (std::size_t v = 0; v + 1 < half_begin.size(); ++v)
      each_edge_up_from(v, [&f, v](int b, std::size_t k) { f(static_cast<int>(v), b, k); });
  }
  std::vector<char> merged;            // an unused exact duplicate of an input vertex (merge_duplicate_vertices)
  std::vector<int> input_to_mesh;      // input vertex id -> mesh vertex id, -1 missing
  std::vector<int> mesh_to_input;      // mesh vertex id -> input vertex id, -1 Steiner
  // Vertex adjacency (index_adjacency): each vertex's smaller neighbours, ascending, at
  // [lower_begin[v], lower_begin[v + 1]) of lower; its larger ones are its bucket's edges.
  std::vector<int> lower_begin, lower;
  std::unordered_map<std::uint64_t, int> listed;      // listed constrained edge -> its segment id (-1 unknown)
  std::unordered_map<std::uint64_t, int> chain_edge;  // edge on a segment chain -> segment id
  std::vector<std::vector<int>> chains;  // per segment: mesh vertex ids from a to b, empty if not found
  std::vector<int> vertex_segment;     // Steiner vertex -> the segment whose chain it is inside, -1 none
  std::vector<char> constrained_half;
  std::vector<signed char> longest;    // per triangle: index i of its longest half-edge (index_triangles)
  // The triangles with an angle below theta's upper bracket (index_triangles, with the
  // angle check on): per range of triangles, in triangle order.
  struct BelowTheta {
    std::size_t t;
    int worst;       // a corner with an angle below theta (the smallest such angle is not needed)
    bool certainly;  // below the lower bracket too: certainly below theta
  };
  std::vector<std::vector<BelowTheta>> below_theta;
  // With one area bound for every triangle (--max-area, no region bounds; index_triangles):
  // the valid triangles above it, per range of triangles, in triangle order. bound 0: not found here.
  struct AreaBound {
    double bound = 0;
    std::vector<std::vector<std::size_t>> above;
  };
  AreaBound area_bound;
  // Per valid triangle, with the Theorem 2 check on (index_triangles): its angle facing
  // its longest edge is over 120 degrees (exact::angle_over_120).
  std::vector<char> largest_over_120;

  const Point& P(int v) const { return mesh.vertices[static_cast<std::size_t>(v)]; }
  const Tri& T(std::size_t t) const { return mesh.triangles[t]; }
  int from(int h) const { return T(static_cast<std::size_t>(h / 3))[static_cast<std::size_t>(h % 3)]; }
  int to(int h) const { return T(static_cast<std::size_t>(h / 3))[static_cast<std::size_t>((h % 3 + 1) % 3)]; }
  int apex(int h) const { return T(static_cast<std::size_t>(h / 3))[static_cast<std::size_t>((h % 3 + 2) % 3)]; }
  int longest_half(std::size_t t) const { return static_cast<int>(3 * t) + longest[t]; }
  bool adjacent(int v, int w) const;
  // Every neighbour of v, ascending: the smaller ones, then the larger ones from v's bucket.
  std::vector<int> neighbors(int v) const;
  // The half-edges of valid triangles on edge v-w (either way), by id: a range of halves.
  std::pair<const Half*, const Half*> halves_on(int v, int w) const;
  // Edge order (ALGORITHM.md section 3): (squared length, -min id, -max id); true iff e > f.
  bool longer(int a, int b, int c, int d) const;
  std::string tri_text(std::size_t t) const;
};

// The certification: inputs, index, and the report the passes add to. With `only`, a
// violation of another group is dropped (neither listed nor counted): one group alone.
struct Certification {
  Certification(const Pslg& pslg, const Mesh& mesh, const Options& opts, Report& out, std::optional<Check> group = {});
  const Options& options;
  Report& report;
  MeshIndex index;
  std::optional<Check> only;

  // Counted always; listed up to Options::max_listed_per_reason per reason.
  void add(Violation v);
};

}  // namespace lepp::certify
