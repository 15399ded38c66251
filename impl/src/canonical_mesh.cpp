// SPDX-License-Identifier: GPL-3.0-or-later
// TriMesh::take_canonical_mesh: the refined mesh in lepp::canonicalize's order by a
// counting sort on each triangle's smallest vertex id, on one thread or two, taking
// the engine's arrays' memory as it goes.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <future>
#include <system_error>
#include <tuple>
#include <type_traits>
#include <utility>

#include "pages.h"
#include "tri_mesh.h"

namespace lepp::fast {
namespace {

// A triangle rotated to start at its smallest id (canonicalize's form).
Tri rotated(const FTri& f) {
  Tri t{f.v(0), f.v(1), f.v(2)};
  while (t[0] > t[1] || t[0] > t[2]) t = {t[1], t[2], t[0]};
  return t;
}

// Bucket counts and places are loads from anywhere in their array (and the places'
// triangles anywhere in the output): the passes fetch them kAhead triangles early.
constexpr std::size_t kAhead = 16;

// The engine's nt triangles: each one counted in its bucket's count[v + 1] (v its
// smallest id), its constrained edges listed once (from its only triangle, or from
// the lower id), and written rotated as a 12-byte Tri into `packed`, the array's own
// bytes, over the 24-byte triangles already read: Tri ti ends at byte 12 ti + 12,
// before triangle ti + 1 begins.
void count_and_pack(const FTri* tris, std::size_t nt, std::uint32_t* count, unsigned char* packed,
                    const SegmentMembership& membership, std::vector<ConstrainedEdge>& edges) {
  for (std::size_t ti = 0; ti < nt; ++ti) {
    if (ti + kAhead < nt) {
      const FTri& g = tris[ti + kAhead];  // not yet overwritten
      __builtin_prefetch(count + std::min({g.v(0), g.v(1), g.v(2)}) + 1, 1);
    }
    const FTri f = tris[ti];
    const Tri r = rotated(f);
    ++count[static_cast<std::size_t>(r[0]) + 1];
    for (int i = 0; i < 3; ++i) {
      if (f.seg(i) < 0 || (f.nbr[i] >= 0 && static_cast<std::size_t>(nbr_tri(f.nbr[i])) < ti)) continue;
      const int a = f.v(next3(i)), b = f.v(prev3(i));
      edges.push_back({std::min(a, b), std::max(a, b), membership.segment_of(a, b)});
    }
    std::memcpy(packed + ti * sizeof(Tri), &r, sizeof r);
  }
}

// The packed triangles in order, each of buckets [lo, hi) to place[v]++ of its
// bucket v in out. kAll: every bucket is in the range. Otherwise the others go to a
// scratch slot, with no branch (which bucket comes next is a coin's toss), and only
// buckets [lo, hi) of place and out are written: another thread can take the rest.
template <bool kAll>
void scatter(const unsigned char* packed, std::size_t nt, std::uint32_t* place, Tri* out, std::uint32_t lo, std::uint32_t hi) {
  std::uint32_t scratch_place = 0;
  Tri scratch;
  auto mine = [&](const Tri& r) { return kAll || static_cast<std::uint32_t>(r[0]) - lo < hi - lo; };
  for (std::size_t ti = 0; ti < nt; ++ti) {
    Tri r;
    if (ti + 2 * kAhead < nt) {
      std::memcpy(&r, packed + (ti + 2 * kAhead) * sizeof(Tri), sizeof r);
      __builtin_prefetch(mine(r) ? place + r[0] : &scratch_place, 1);
    }
    if (ti + kAhead < nt) {
      std::memcpy(&r, packed + (ti + kAhead) * sizeof(Tri), sizeof r);
      if (mine(r)) __builtin_prefetch(out + place[r[0]], 1);
    }
    std::memcpy(&r, packed + ti * sizeof(Tri), sizeof r);
    const bool its = mine(r);
    std::uint32_t* const p = its ? place + r[0] : &scratch_place;
    Tri* const d = its ? out + *p : &scratch;
    *d = r;
    ++*p;
  }
}

// Buckets [from, to): bucket v is out[end[v - 1] .. end[v]) (from 0 for v = 0), its
// triangles all starting at v; each sorted by the other two ids. A bucket holds
// about two triangles (a mesh has twice as many triangles as vertices): an
// insertion sort in place of std::sort's calls for each; std::sort for a large one
// (a vertex of high degree, as in a fan left unrefined).
void sort_buckets(Tri* out, const std::uint32_t* end, std::size_t from, std::size_t to) {
  for (std::size_t v = from; v < to; ++v) {
    Tri* const first = out + (v ? end[v - 1] : 0);
    Tri* const last = out + end[v];
    if (last - first > 16) {
      std::sort(first, last);
      continue;
    }
    for (Tri* i = first + (first != last); i < last; ++i) {
      const Tri t = *i;
      Tri* j = i;
      for (; j > first && (t[1] < (j - 1)[0][1] || (t[1] == (j - 1)[0][1] && t[2] < (j - 1)[0][2])); --j) *j = *(j - 1);
      *j = t;
    }
  }
}

// f on a thread of its own; an invalid future where no thread can be made (this
// thread then does the work itself).
template <class F>
std::future<void> start_beside(F&& f) {
  try {
    return std::async(std::launch::async, std::forward<F>(f));
  } catch (const std::system_error&) {
    return {};
  }
}

}  // namespace

Mesh TriMesh::take_canonical_mesh(const SegmentMembership& membership, int threads, std::size_t split_from) {
  Mesh mesh;
  mesh.input_vertices = static_cast<std::size_t>(membership.input_vertices);
  const std::size_t nv = pts.size(), nt = tris.size();
  mesh.vertices = std::move(pts);
  pts = {};
  // Freed before the output's arrays are made: the peak memory is here.
  stamp = {};
  region = {};
  // Below this, the output's few pages are faulted rather than moved (two calls more).
  constexpr std::size_t kMovedFrom = std::size_t{1} << 16;
  static_assert(sizeof(Tri) <= sizeof(FTri) && std::is_trivially_copyable_v<FTri> && std::is_trivially_copyable_v<Tri>);
  const FTri* const ftris = tris.data();
  unsigned char* const packed = reinterpret_cast<unsigned char*>(tris.data());
  std::vector<std::uint32_t> start(nv + 1, 0);
  std::vector<ConstrainedEdge> edges;

  // First pass: the buckets counted, the constrained edges listed, the triangles
  // packed in place.
  count_and_pack(ftris, nt, start.data(), packed, membership, edges);
  for (std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];  // start[v]: where bucket v begins

  // The rest of the engine's array backs the output's triangles: the two never hold
  // 24 + 12 bytes per triangle at once, and the output takes no fresh pages.
  mesh.triangles.reserve(nt);
  unsigned char* const rest = packed + nt * sizeof(Tri);
  unsigned char* const storage = reinterpret_cast<unsigned char*>(mesh.triangles.data());
  if (nt * sizeof(Tri) < kMovedFrom || !move_pages(rest, packed + nt * sizeof(FTri), storage, storage + nt * sizeof(Tri)))
    release_pages(rest, packed + nt * sizeof(FTri));
  mesh.triangles.resize(nt);
  Tri* const out = mesh.triangles.data();

  // Second pass: each triangle to its bucket's next free place; afterwards start[v]
  // is where bucket v ends. Third: each bucket sorted. On two threads each takes
  // the buckets on its side of the one where half the triangles lie below (each
  // reads every triangle and writes only its own buckets, so no memory is added):
  // the same places, so the same mesh.
  const bool split = threads > 1 && nt >= split_from;
  const auto middle = static_cast<std::uint32_t>(
      std::lower_bound(start.begin(), start.begin() + static_cast<std::ptrdiff_t>(nv), static_cast<std::uint32_t>(nt / 2)) -
      start.begin());
  std::future<void> beside;
  if (split) beside = start_beside([&] { scatter<false>(packed, nt, start.data(), out, middle, static_cast<std::uint32_t>(nv)); });
  if (beside.valid()) {
    scatter<false>(packed, nt, start.data(), out, 0, middle);
    beside.get();
    tris = {};
    beside = start_beside([&] { sort_buckets(out, start.data(), middle, nv); });
    sort_buckets(out, start.data(), 0, beside.valid() ? middle : nv);
    if (beside.valid()) beside.get();
  } else {
    scatter<true>(packed, nt, start.data(), out, 0, 0);
    tris = {};
    sort_buckets(out, start.data(), 0, nv);
  }

  // Constrained edges: few; a plain sort in canonicalize's order.
  std::sort(edges.begin(), edges.end(), [](const ConstrainedEdge& x, const ConstrainedEdge& y) {
    return std::tie(x.a, x.b, x.segment) < std::tie(y.a, y.b, y.segment);
  });
  mesh.constrained_edges = std::move(edges);
  return mesh;
}

}  // namespace lepp::fast
