// SPDX-License-Identifier: GPL-3.0-or-later
// The fast engine's triangle mesh: flat arrays, integer ids, no pointers.
//
// Triangle t has vertices v(0..2) counter-clockwise; edge i is the edge
// opposite v(i), from v(i+1) to v(i+2). nbr[i] is the neighbour across edge i,
// encoded as (triangle << 2) | (its index of that edge), or -1 on the domain
// boundary; seg(i) is 0 when edge i is constrained, -1 when not (which input
// segment it lies on follows from its endpoints: SegmentMembership::segment_of).
// 24 bytes a triangle: the flips are bound by memory traffic, and the triangles
// are most of the peak memory (issue 40). Triangles are rewritten in place by
// insertions and flips and never freed, so the arrays only grow.
#pragma once
#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "lepp/mesh.h"
#include "lepp/pslg.h"

namespace lepp::fast {

// The constrained flags and the longest-edge cache ride in the vertex words'
// top bits: a vertex id takes 29 bits (nbr's codes already hold a triangle id in
// 29, and a mesh has about twice as many triangles as vertices).
class FTri {
 public:
  // Uninitialized, as a slot grown for put() is overwritten at once: growing
  // the array writes no zeros (std::vector::resize value-initializes).
  FTri() {}
  FTri(const int (&v)[3], const int (&n)[3], const std::int8_t (&s)[3], int longest = -1)
      : nbr{n[0], n[1], n[2]},
        w_{word(v[0], s[0]) | longest_bits(longest), word(v[1], s[1]), word(v[2], s[2])} {}

  int v(int i) const { return static_cast<int>(w_[i] & kId); }
  std::int8_t seg(int i) const { return (w_[i] & kConstrained) ? 0 : -1; }
  // The index of the longest edge in the edge order, -1 until computed.
  int longest() const { return static_cast<int>(w_[0] >> kLongestShift & 3) - 1; }

  void set_v(int i, int id) { w_[i] = (w_[i] & ~kId) | static_cast<std::uint32_t>(id); }
  void set_seg(int i, std::int8_t s) { w_[i] = s >= 0 ? (w_[i] | kConstrained) : (w_[i] & ~kConstrained); }
  void set_longest(int l) { w_[0] = (w_[0] & ~(std::uint32_t{3} << kLongestShift)) | longest_bits(l); }

  int nbr[3];

  // A vertex id's bits (capacity.h guards them).
  static constexpr int kIdBits = 29;

 private:
  static constexpr std::uint32_t kId = (std::uint32_t{1} << kIdBits) - 1;
  static constexpr int kLongestShift = 29;  // longest + 1 in bits 29, 30 of w_[0]
  static constexpr std::uint32_t kConstrained = std::uint32_t{1} << 31;
  static std::uint32_t word(int v, std::int8_t s) { return static_cast<std::uint32_t>(v) | (s >= 0 ? kConstrained : 0); }
  static std::uint32_t longest_bits(int l) { return static_cast<std::uint32_t>(l + 1) << kLongestShift; }
  std::uint32_t w_[3];
};
static_assert(sizeof(FTri) == 24);

inline int next3(int i) { return i == 2 ? 0 : i + 1; }
inline int prev3(int i) { return i == 0 ? 2 : i - 1; }
inline int nbr_tri(int code) { return code >> 2; }
inline int nbr_edge(int code) { return code & 3; }
inline int nbr_code(int t, int i) { return (t << 2) | i; }

// Which input segments each vertex lies on (ALGORITHM.md section 1): input
// vertices every segment they end, Steiner points on split edges their one segment.
struct SegmentMembership {
  std::vector<int> start;     // input vertex v: its segments are list[start[v] .. start[v+1])
  std::vector<int> list;
  int input_vertices = 0;
  const std::vector<Segment>* segments = nullptr;

  // Steiner point n + k lies on a segment iff bit k of steiner_on is set; then
  // steiner_segments holds (k, that segment), in increasing k. Most Steiner points
  // lie on none: a bit each, not an int (2 bytes a triangle of the peak, issue 40).
  std::vector<std::uint64_t> steiner_on;
  std::vector<std::pair<int, int>> steiner_segments;
  int steiner_count = 0;

  // The next Steiner point, on `segment` (-1: on none).
  void add_steiner(int segment) {
    const auto k = static_cast<std::size_t>(steiner_count++);
    if (k / 64 == steiner_on.size()) steiner_on.push_back(0);
    if (segment < 0) return;
    steiner_on[k / 64] |= std::uint64_t{1} << (k % 64);
    steiner_segments.emplace_back(static_cast<int>(k), segment);
  }
  // The segment of Steiner point v (v >= input_vertices), or -1.
  int steiner_segment(int v) const {
    const int k = v - input_vertices;
    const auto uk = static_cast<std::size_t>(k);
    if (!(steiner_on[uk / 64] >> (uk % 64) & 1)) return -1;
    return std::lower_bound(steiner_segments.begin(), steiner_segments.end(), k,
                            [](const std::pair<int, int>& e, int key) { return e.first < key; })
        ->second;
  }

  // Calls f(segment) for each segment vertex v lies on.
  template <class F>
  void for_each(int v, F&& f) const {
    if (v < input_vertices) {
      for (int k = start[static_cast<std::size_t>(v)]; k < start[static_cast<std::size_t>(v) + 1]; ++k)
        f(list[static_cast<std::size_t>(k)]);
    } else if (int s = steiner_segment(v); s >= 0) {
      f(s);
    }
  }
  // The input segment of the constrained edge ab: a Steiner endpoint's segment,
  // else the segment joining the two input vertices.
  int segment_of(int a, int b) const {
    if (a >= input_vertices) return steiner_segment(a);
    if (b >= input_vertices) return steiner_segment(b);
    for (int k = start[static_cast<std::size_t>(a)]; k < start[static_cast<std::size_t>(a) + 1]; ++k) {
      const Segment& s = (*segments)[static_cast<std::size_t>(list[static_cast<std::size_t>(k)])];
      if (s.a == b || s.b == b) return list[static_cast<std::size_t>(k)];
    }
    return -1;
  }
  bool on_any(int v) const {
    if (v < input_vertices) return start[static_cast<std::size_t>(v)] < start[static_cast<std::size_t>(v) + 1];
    const auto k = static_cast<std::size_t>(v - input_vertices);
    return steiner_on[k / 64] >> (k % 64) & 1;
  }
};

SegmentMembership make_membership(const Pslg& pslg);

struct TriMesh {
  std::vector<Point> pts;
  std::vector<FTri> tris;
  // Bumped whenever a slot is rewritten: a queued triangle is still in the mesh
  // iff its slot's stamp is unchanged (a rewrite always destroys the old triangle).
  // A small array, so checking a stale queue entry costs no miss on tris.
  std::vector<std::uint32_t> stamp;
  // Only with region area bounds (empty otherwise, so the splits below test one
  // pointer pair): the region of each triangle, 0 for none, k + 1 for the PSLG's
  // region k. A split's new slots take the region of the triangle they split (a
  // split edge's two sides keep theirs); a flip never crosses a constrained edge,
  // so both its triangles are in one region and each slot keeps its value.
  std::vector<std::int32_t> region;
  // Whether longest_edge fills the triangles' cache: false while other threads
  // read the mesh (edge_order.h).
  bool cache_longest = true;

  const Point& p(int v) const { return pts[static_cast<std::size_t>(v)]; }
  FTri& t(int i) { return tris[static_cast<std::size_t>(i)]; }
  const FTri& t(int i) const { return tris[static_cast<std::size_t>(i)]; }
  int size() const { return static_cast<int>(tris.size()); }

  // Reserves room for a refinement of this size. Untouched capacity costs no
  // memory. No huge pages (madvise): on the project machine (a VM) the kernel's
  // zeroing of each new 2 MiB page cost up to 2.5 s of system time at 10^7
  // triangles, near the run's 3.3 s of user time, and saved no measurable user
  // time (docs/BENCHMARKS.md, issue 31).
  void reserve(std::size_t vertices, std::size_t triangles);

  void put(int ti, const FTri& f) {
    t(ti) = f;
    ++stamp[static_cast<std::size_t>(ti)];
  }
  // One slot at a time: resize's general path (std::vector's _M_fill_insert and
  // _M_default_append, not inlined) cost about 100 instructions an insertion.
  void grow(std::size_t k) {
    for (std::size_t i = 0; i < k; ++i) {
      tris.emplace_back();  // FTri() writes nothing: put() fills the slot
      stamp.push_back(0);
    }
  }
  // Slot `to` (just grown) lies in the region of slot `from`.
  void inherit_region(int from, int to) {
    if (region.empty()) return;
    region.resize(tris.size(), 0);
    region[static_cast<std::size_t>(to)] = region[static_cast<std::size_t>(from)];
  }

  // Points the neighbour across (t, i) back at `code`.
  void relink(int code_of_neighbour, int code) {
    if (code_of_neighbour >= 0) t(nbr_tri(code_of_neighbour)).nbr[nbr_edge(code_of_neighbour)] = code;
  }

  // Splits triangle ti at vertex p strictly inside it into three triangles, each
  // with p as v[0] (so edge 0 is the one to test for a flip). Writes their ids to out.
  void split_triangle(int ti, int p, int out[3]);

  // Splits edge i of triangle ti at vertex p, and the neighbour across it if any;
  // the two halves keep its flag `segment` (0 constrained, -1 not). Every new
  // triangle has p as v[0]. Writes the 2 or 4 ids to out, returns how many.
  int split_edge(int ti, int i, int p, std::int8_t segment, int out[4]);

  // The split of constrained edge i of ti = (c, a, b) at p strictly off the line
  // ab when the triangle on the side p moves away from stays (ALGORITHM.md
  // section 6, "A split off its line"): that triangle K keeps its slot, stamp and
  // vertices, its edge ab becomes unconstrained, and the sliver between ab and
  // the new constrained edges ap, pb joins K's side. keep_neighbour: K is the
  // triangle (d, b, a) across edge i (p on c's side), else K is ti (p on the
  // other side, which may be outside the domain). Writes the new triangles (each
  // with p at v[0]) to out, returns how many (3, or 1 without a neighbour); k = K.
  int split_edge_keeping(int ti, int i, int p, bool keep_neighbour, int out[3], int& k);

  // Flips edge 0 of ti = (p, a, b) with the triangle (d, b, a) across it: ti
  // becomes (p, a, d) and the neighbour (p, d, b), both with p as v[0]. Returns
  // the neighbour's id.
  int flip_edge0(int ti);

  // Calls f(tri) for every triangle with vertex p at v[0] around p, starting at
  // ti (which must have p at v[0]; true of the triangles an insertion makes).
  template <class F>
  void for_each_in_star(int ti, F&& f) const;

  // Domain triangles as a Mesh (vertices in id order, not canonicalized).
  Mesh to_mesh(const SegmentMembership& membership) const;
  // The mesh in lepp::canonicalize's order (a bucket sort: linear time), taking
  // the arrays' memory as it goes (the triangles packed in place first, so the
  // peak stays that of the refinement): this TriMesh is empty afterwards
  // (canonical_mesh.cpp). With threads > 1 and at least split_from triangles, its
  // second and third passes run on two threads (the same mesh, no more memory).
  static constexpr std::size_t kCanonicalSplitFrom = std::size_t{1} << 16;
  Mesh take_canonical_mesh(const SegmentMembership& membership, int threads = 1,
                           std::size_t split_from = kCanonicalSplitFrom);
};

template <class F>
void TriMesh::for_each_in_star(int ti, F&& f) const {
  // Around p counter-clockwise: leave each triangle (p, a, b) through edge 1 (b, p);
  // the next triangle (p, b, c) has that edge as its edge 2.
  int cur = ti;
  for (;;) {
    f(cur);
    int code = t(cur).nbr[1];
    if (code < 0) break;  // p lies on the boundary: go the other way from ti
    cur = nbr_tri(code);
    if (cur == ti) return;
  }
  cur = ti;
  for (;;) {
    int code = t(cur).nbr[2];
    if (code < 0) return;
    cur = nbr_tri(code);
    f(cur);
  }
}

inline void TriMesh::split_triangle(int ti, int p, int out[3]) {
  const FTri old = t(ti);
  const int a = old.v(0), b = old.v(1), c = old.v(2);
  const int t0 = ti, t1 = size(), t2 = size() + 1;
  grow(2);
  // t0 = (p, b, c), t1 = (p, c, a), t2 = (p, a, b); edge 0 of each is an old edge.
  put(t0, FTri{{p, b, c}, {old.nbr[0], nbr_code(t1, 2), nbr_code(t2, 1)}, {old.seg(0), -1, -1}, -1});
  put(t1, FTri{{p, c, a}, {old.nbr[1], nbr_code(t2, 2), nbr_code(t0, 1)}, {old.seg(1), -1, -1}, -1});
  put(t2, FTri{{p, a, b}, {old.nbr[2], nbr_code(t0, 2), nbr_code(t1, 1)}, {old.seg(2), -1, -1}, -1});
  relink(old.nbr[0], nbr_code(t0, 0));
  relink(old.nbr[1], nbr_code(t1, 0));
  relink(old.nbr[2], nbr_code(t2, 0));
  inherit_region(t0, t1);
  inherit_region(t0, t2);
  out[0] = t0, out[1] = t1, out[2] = t2;
}

inline int TriMesh::split_edge(int ti, int i, int p, std::int8_t segment, int out[4]) {
  const FTri old = t(ti);
  const int c = old.v(i), a = old.v(next3(i)), b = old.v(prev3(i));
  const int na = old.nbr[next3(i)];
  const std::int8_t sa = old.seg(next3(i));  // edge (b, c), opposite a
  const int nb = old.nbr[prev3(i)];
  const std::int8_t sb = old.seg(prev3(i));  // edge (c, a), opposite b
  const int across = old.nbr[i];
  const int t0 = ti, t1 = size();
  if (across < 0) {
    grow(1);
    put(t0, FTri{{p, b, c}, {na, nbr_code(t1, 2), -1}, {sa, -1, segment}, -1});
    put(t1, FTri{{p, c, a}, {nb, -1, nbr_code(t0, 1)}, {sb, segment, -1}, -1});
    relink(na, nbr_code(t0, 0));
    relink(nb, nbr_code(t1, 0));
    inherit_region(t0, t1);
    out[0] = t0, out[1] = t1;
    return 2;
  }
  // The neighbour (d, b, a): j is its index of the shared edge.
  const int n0 = nbr_tri(across), j = nbr_edge(across), n1 = t1 + 1;
  const FTri on = t(n0);
  const int d = on.v(j);
  const int mb = on.nbr[next3(j)];
  const std::int8_t smb = on.seg(next3(j));  // edge (a, d), opposite b
  const int ma = on.nbr[prev3(j)];
  const std::int8_t sma = on.seg(prev3(j));  // edge (d, b), opposite a
  grow(2);
  put(t0, FTri{{p, b, c}, {na, nbr_code(t1, 2), nbr_code(n1, 1)}, {sa, -1, segment}, -1});
  put(t1, FTri{{p, c, a}, {nb, nbr_code(n0, 2), nbr_code(t0, 1)}, {sb, segment, -1}, -1});
  put(n0, FTri{{p, a, d}, {mb, nbr_code(n1, 2), nbr_code(t1, 1)}, {smb, -1, segment}, -1});
  put(n1, FTri{{p, d, b}, {ma, nbr_code(t0, 2), nbr_code(n0, 1)}, {sma, segment, -1}, -1});
  relink(na, nbr_code(t0, 0));
  relink(nb, nbr_code(t1, 0));
  relink(mb, nbr_code(n0, 0));
  relink(ma, nbr_code(n1, 0));
  inherit_region(t0, t1);  // ti's side of the split edge
  inherit_region(n0, n1);  // the neighbour's side: its own region across a segment
  out[0] = t0, out[1] = t1, out[2] = n0, out[3] = n1;
  return 4;
}

inline int TriMesh::split_edge_keeping(int ti, int i, int p, bool keep_neighbour, int out[3], int& k) {
  const FTri old = t(ti);
  const int c = old.v(i), a = old.v(next3(i)), b = old.v(prev3(i));
  const int across = old.nbr[i];
  if (keep_neighbour) {
    // K = (d, b, a) across ab stays; ti's side becomes (p, b, c), (p, c, a) and
    // the sliver (p, a, b), counter-clockwise as p lies on c's side of ab.
    const int na = old.nbr[next3(i)], nb = old.nbr[prev3(i)];
    const std::int8_t sa = old.seg(next3(i)), sb = old.seg(prev3(i));
    const int n0 = nbr_tri(across), j = nbr_edge(across);
    const int t0 = ti, t1 = size(), s = size() + 1;
    grow(2);
    put(t0, FTri{{p, b, c}, {na, nbr_code(t1, 2), nbr_code(s, 1)}, {sa, -1, 0}, -1});
    put(t1, FTri{{p, c, a}, {nb, nbr_code(s, 2), nbr_code(t0, 1)}, {sb, 0, -1}, -1});
    put(s, FTri{{p, a, b}, {nbr_code(n0, j), nbr_code(t0, 2), nbr_code(t1, 1)}, {-1, 0, 0}, -1});
    relink(na, nbr_code(t0, 0));
    relink(nb, nbr_code(t1, 0));
    t(n0).nbr[j] = nbr_code(s, 0);  // K itself is not rewritten: its stamp stays
    t(n0).set_seg(j, -1);
    inherit_region(t0, t1);
    inherit_region(n0, s);  // the sliver lies on K's side of ap, pb
    k = n0;
    out[0] = t0, out[1] = t1, out[2] = s;
    return 3;
  }
  // K = ti stays; the sliver (p, b, a) lies beyond ab, counter-clockwise as p
  // lies on the far side; the neighbour (d, b, a), if any, becomes (p, a, d), (p, d, b).
  const int s = size();
  grow(1);
  t(ti).nbr[i] = nbr_code(s, 0);
  t(ti).set_seg(i, -1);
  inherit_region(ti, s);
  k = ti;
  if (across < 0) {
    put(s, FTri{{p, b, a}, {nbr_code(ti, i), -1, -1}, {-1, 0, 0}, -1});
    out[0] = s;
    return 1;
  }
  const int n0 = nbr_tri(across), j = nbr_edge(across), n1 = size();
  const FTri on = t(n0);
  const int d = on.v(j);
  const int mb = on.nbr[next3(j)], ma = on.nbr[prev3(j)];
  const std::int8_t smb = on.seg(next3(j)), sma = on.seg(prev3(j));  // edges (a, d), (d, b)
  grow(1);
  put(s, FTri{{p, b, a}, {nbr_code(ti, i), nbr_code(n0, 2), nbr_code(n1, 1)}, {-1, 0, 0}, -1});
  put(n0, FTri{{p, a, d}, {mb, nbr_code(n1, 2), nbr_code(s, 1)}, {smb, -1, 0}, -1});
  put(n1, FTri{{p, d, b}, {ma, nbr_code(s, 2), nbr_code(n0, 1)}, {sma, 0, -1}, -1});
  relink(mb, nbr_code(n0, 0));
  relink(ma, nbr_code(n1, 0));
  inherit_region(n0, n1);
  out[0] = s, out[1] = n0, out[2] = n1;
  return 3;
}

inline int TriMesh::flip_edge0(int ti) {
  const FTri old = t(ti);
  const int p = old.v(0), a = old.v(1), b = old.v(2);
  const int ni = nbr_tri(old.nbr[0]), j = nbr_edge(old.nbr[0]);
  const FTri on = t(ni);  // (d, b, a) from index j
  const int d = on.v(j);
  const int m1 = on.nbr[next3(j)];
  const std::int8_t s1 = on.seg(next3(j));  // edge (a, d)
  const int m2 = on.nbr[prev3(j)];
  const std::int8_t s2 = on.seg(prev3(j));  // edge (d, b)
  // ti = (p, a, d), ni = (p, d, b).
  put(ti, FTri{{p, a, d}, {m1, nbr_code(ni, 2), old.nbr[2]}, {s1, -1, old.seg(2)}, -1});
  put(ni, FTri{{p, d, b}, {m2, old.nbr[1], nbr_code(ti, 1)}, {s2, old.seg(1), -1}, -1});
  relink(m1, nbr_code(ti, 0));
  relink(m2, nbr_code(ni, 0));
  relink(old.nbr[1], nbr_code(ni, 1));
  return ni;
}

}  // namespace lepp::fast
