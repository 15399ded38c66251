// SPDX-License-Identifier: GPL-3.0-or-later
// TriMesh::take_canonical_mesh: the refined mesh in lepp::canonicalize's order by a
// counting sort on each triangle's smallest vertex id, on one thread or two, taking
// the engine's arrays' memory as it goes.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <future>
#include <tuple>
#include <type_traits>
#include <utility>

#include "tri_mesh.h"

#ifdef __linux__
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace lepp::fast {
namespace {

// Returns the whole pages within [begin, end) to the system (their contents are
// no longer needed); elsewhere than on Linux, nothing.
void release_pages(unsigned char* begin, unsigned char* end) {
#ifdef __linux__
  const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
  const std::uintptr_t from = (reinterpret_cast<std::uintptr_t>(begin) + page - 1) & ~(page - 1);
  const std::uintptr_t to = reinterpret_cast<std::uintptr_t>(end) & ~(page - 1);
  if (to > from) madvise(reinterpret_cast<void*>(from), to - from, MADV_DONTNEED);
#else
  (void)begin;
  (void)end;
#endif
}

// A triangle rotated to start at its smallest id (canonicalize's form).
Tri rotated(const FTri& f) {
  Tri t{f.v(0), f.v(1), f.v(2)};
  while (t[0] > t[1] || t[0] > t[2]) t = {t[1], t[2], t[0]};
  return t;
}

// Bucket counts and places are loads from anywhere in their array (and the places'
// triangles anywhere in the output): the passes fetch them kAhead triangles early.
constexpr std::size_t kAhead = 16;

// Triangles [from, to) of the engine's array: each one counted in its bucket's
// count[v + 1] (v its smallest id), its constrained edges listed once (from its
// only triangle, or from the lower id). With `packed` (the array's own bytes), each
// is also written there rotated as a 12-byte Tri, over the 24-byte triangles
// already read: Tri ti ends at byte 12 ti + 12, before triangle ti + 1 begins.
void count_and_pack(const FTri* tris, std::size_t from, std::size_t to, std::uint32_t* count, unsigned char* packed,
                    const SegmentMembership& membership, std::vector<ConstrainedEdge>& edges) {
  for (std::size_t ti = from; ti < to; ++ti) {
    if (ti + kAhead < to) {
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
    if (packed) std::memcpy(packed + ti * sizeof(Tri), &r, sizeof r);
  }
}

// count_and_pack's packing alone, in increasing order (each write lies below what
// is still to be read).
void pack(const FTri* tris, std::size_t from, std::size_t to, unsigned char* packed) {
  for (std::size_t ti = from; ti < to; ++ti) {
    const Tri r = rotated(tris[ti]);
    std::memcpy(packed + ti * sizeof(Tri), &r, sizeof r);
  }
}

// Packed triangles [from, to), in order, each to place[v]++ of its bucket v in out.
void scatter(const unsigned char* packed, std::size_t from, std::size_t to, std::uint32_t* place, Tri* out) {
  for (std::size_t ti = from; ti < to; ++ti) {
    Tri r;
    if (ti + 2 * kAhead < to) {
      std::memcpy(&r, packed + (ti + 2 * kAhead) * sizeof(Tri), sizeof r);
      __builtin_prefetch(place + r[0], 1);
    }
    if (ti + kAhead < to) {
      std::memcpy(&r, packed + (ti + kAhead) * sizeof(Tri), sizeof r);
      __builtin_prefetch(out + place[static_cast<std::size_t>(r[0])], 1);
    }
    std::memcpy(&r, packed + ti * sizeof(Tri), sizeof r);
    out[place[static_cast<std::size_t>(r[0])]++] = r;
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
  static_assert(sizeof(Tri) <= sizeof(FTri) && std::is_trivially_copyable_v<FTri> && std::is_trivially_copyable_v<Tri>);
  const FTri* const ftris = tris.data();
  unsigned char* const packed = reinterpret_cast<unsigned char*>(tris.data());

  // Two threads split the triangles at h: each pass runs on both halves at once,
  // with a count (then place) array for each half, so that no two threads write
  // one word. The output is the same: a bucket's triangles from the first half
  // go before those from the second, each half in its order, as one pass puts them.
  const bool split = threads > 1 && nt >= split_from;
  const std::size_t h = split ? nt / 2 : nt;
  std::vector<std::uint32_t> start(nv + 1, 0), second(split ? nv + 1 : 0, 0);
  std::vector<ConstrainedEdge> edges;

  // First pass: the buckets counted, the constrained edges listed, the triangles
  // packed in place. The second half's triangles lie beyond the bytes the first
  // half's packing writes, so its thread counts them as they are, and they are
  // packed after the first half (in order: each write below what is left to read).
  if (split) {
    std::vector<ConstrainedEdge> edges_second;
    auto rest = std::async(std::launch::async,
                           [&] { count_and_pack(ftris, h, nt, second.data(), nullptr, membership, edges_second); });
    count_and_pack(ftris, 0, h, start.data(), packed, membership, edges);
    rest.get();
    pack(ftris, h, nt, packed);
    edges.insert(edges.end(), edges_second.begin(), edges_second.end());
  } else {
    count_and_pack(ftris, 0, nt, start.data(), packed, membership, edges);
  }
  // The rest of the array is given back before the output's triangles are made,
  // so the two never hold 24 + 12 bytes per triangle at once.
  release_pages(packed + nt * sizeof(Tri), packed + nt * sizeof(FTri));

  // Second pass: each triangle to its bucket's next free place. Bucket v begins at
  // S(v), the triangles of the buckets before it; the second half's part of it
  // after the first half's. Afterwards bucket v ends at end[v].
  if (split) {
    std::uint32_t run = 0;
    for (std::size_t v = 0; v < nv; ++v) {
      const std::uint32_t first_half = start[v + 1], second_half = second[v + 1];
      start[v] = run;
      second[v] = run + first_half;
      run += first_half + second_half;
    }
  } else {
    for (std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  }
  mesh.triangles.resize(nt);
  Tri* const out = mesh.triangles.data();
  if (split) {
    auto rest = std::async(std::launch::async, [&] { scatter(packed, h, nt, second.data(), out); });
    scatter(packed, 0, h, start.data(), out);
    rest.get();
  } else {
    scatter(packed, 0, nt, start.data(), out);
  }
  tris = {};

  // Third pass: each bucket sorted; split at the bucket where half the triangles lie below.
  const std::uint32_t* const end = split ? second.data() : start.data();
  if (split) {
    const std::size_t middle =
        static_cast<std::size_t>(std::lower_bound(end, end + nv, static_cast<std::uint32_t>(nt / 2)) - end);
    auto rest = std::async(std::launch::async, [&] { sort_buckets(out, end, middle, nv); });
    sort_buckets(out, end, 0, middle);
    rest.get();
  } else {
    sort_buckets(out, end, 0, nv);
  }

  // Constrained edges: few; a plain sort in canonicalize's order.
  std::sort(edges.begin(), edges.end(), [](const ConstrainedEdge& x, const ConstrainedEdge& y) {
    return std::tie(x.a, x.b, x.segment) < std::tie(y.a, y.b, y.segment);
  });
  mesh.constrained_edges = std::move(edges);
  return mesh;
}

}  // namespace lepp::fast
