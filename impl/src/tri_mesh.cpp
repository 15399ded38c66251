// SPDX-License-Identifier: GPL-3.0-or-later
// The cold parts of the flat mesh: segment membership and conversion to Mesh.
#include "tri_mesh.h"

#include <fmt/format.h>

#include "capacity.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <tuple>
#include <type_traits>
#include <utility>

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

}  // namespace

SegmentMembership make_membership(const Pslg& pslg) {
  SegmentMembership m;
  m.input_vertices = static_cast<int>(pslg.vertices.size());
  m.segments = &pslg.segments;
  m.start.assign(pslg.vertices.size() + 1, 0);
  for (const Segment& s : pslg.segments) {
    ++m.start[static_cast<std::size_t>(s.a) + 1];
    ++m.start[static_cast<std::size_t>(s.b) + 1];
  }
  for (std::size_t v = 0; v < pslg.vertices.size(); ++v) m.start[v + 1] += m.start[v];
  m.list.resize(2 * pslg.segments.size());
  std::vector<int> fill(m.start.begin(), m.start.end() - 1);
  // Segment ids ascend within each vertex's list.
  for (std::size_t k = 0; k < pslg.segments.size(); ++k) {
    const Segment& s = pslg.segments[k];
    m.list[static_cast<std::size_t>(fill[static_cast<std::size_t>(s.a)]++)] = static_cast<int>(k);
    m.list[static_cast<std::size_t>(fill[static_cast<std::size_t>(s.b)]++)] = static_cast<int>(k);
  }
  return m;
}

void TriMesh::reserve(std::size_t vertices, std::size_t triangles) {
  pts.reserve(vertices);
  tris.reserve(triangles);
  stamp.reserve(triangles);
  if (!region.empty()) region.reserve(triangles);
}

Mesh TriMesh::to_mesh(const SegmentMembership& membership) const {
  Mesh mesh;
  mesh.vertices = pts;
  mesh.input_vertices = static_cast<std::size_t>(membership.input_vertices);
  mesh.triangles.reserve(tris.size());
  for (int ti = 0; ti < size(); ++ti) {
    const FTri& f = t(ti);
    mesh.triangles.push_back({f.v(0), f.v(1), f.v(2)});
    for (int i = 0; i < 3; ++i) {
      if (f.seg(i) < 0) continue;
      // Each constrained edge once: from its only triangle, or from the lower id.
      if (f.nbr[i] >= 0 && nbr_tri(f.nbr[i]) < ti) continue;
      int a = f.v(next3(i)), b = f.v(prev3(i));
      mesh.constrained_edges.push_back({a, b, membership.segment_of(a, b)});
    }
  }
  return mesh;
}

Mesh TriMesh::take_canonical_mesh(const SegmentMembership& membership) {
  Mesh mesh;
  mesh.input_vertices = static_cast<std::size_t>(membership.input_vertices);
  const std::size_t nv = pts.size(), nt = tris.size();
  mesh.vertices = std::move(pts);
  pts = {};
  // Freed before the output's arrays are made: the peak memory is here.
  stamp = {};
  region = {};
  auto rotated = [](const FTri& f) {
    Tri t{f.v(0), f.v(1), f.v(2)};
    while (t[0] > t[1] || t[0] > t[2]) t = {t[1], t[2], t[0]};
    return t;
  };
  // First pass: each triangle rotated to start at its smallest id, written as a
  // 12-byte Tri at the front of the engine's own array, over the 24-byte triangles
  // already read (Tri i ends at byte 12 i + 12, before triangle i + 1 begins), and
  // its constrained edges; the bucket sizes counted.
  static_assert(sizeof(Tri) <= sizeof(FTri) && std::is_trivially_copyable_v<FTri> && std::is_trivially_copyable_v<Tri>);
  unsigned char* packed = reinterpret_cast<unsigned char*>(tris.data());
  std::vector<std::uint32_t> start(nv + 1, 0);
  std::vector<ConstrainedEdge> edges;
  // Bucket counts and places are loads from anywhere in start (and the places'
  // triangles anywhere in the output): both passes fetch them kAhead triangles early.
  constexpr std::size_t kAhead = 16;
  for (std::size_t ti = 0; ti < nt; ++ti) {
    if (ti + kAhead < nt) {
      const FTri& g = tris[ti + kAhead];  // not yet overwritten: Tri ti ends before it
      __builtin_prefetch(start.data() + std::min({g.v(0), g.v(1), g.v(2)}) + 1, 1);
    }
    const FTri f = tris[ti];
    const Tri r = rotated(f);
    ++start[static_cast<std::size_t>(r[0]) + 1];
    for (int i = 0; i < 3; ++i) {
      if (f.seg(i) < 0 || (f.nbr[i] >= 0 && static_cast<std::size_t>(nbr_tri(f.nbr[i])) < ti)) continue;
      int a = f.v(next3(i)), b = f.v(prev3(i));
      edges.push_back({std::min(a, b), std::max(a, b), membership.segment_of(a, b)});
    }
    std::memcpy(packed + ti * sizeof(Tri), &r, sizeof r);
  }
  // The rest of the array is given back before the output's triangles are made,
  // so the two never hold 24 + 12 bytes per triangle at once.
  release_pages(packed + nt * sizeof(Tri), packed + nt * sizeof(FTri));
  // Second pass: a counting sort by the smallest id into the output; start[v] is
  // bucket v's next free place, so afterwards bucket v ends at start[v].
  for (std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  mesh.triangles.resize(nt);
  for (std::size_t ti = 0; ti < nt; ++ti) {
    Tri r;
    if (ti + 2 * kAhead < nt) {
      std::memcpy(&r, packed + (ti + 2 * kAhead) * sizeof(Tri), sizeof r);
      __builtin_prefetch(start.data() + r[0], 1);
    }
    if (ti + kAhead < nt) {
      std::memcpy(&r, packed + (ti + kAhead) * sizeof(Tri), sizeof r);
      __builtin_prefetch(mesh.triangles.data() + start[static_cast<std::size_t>(r[0])], 1);
    }
    std::memcpy(&r, packed + ti * sizeof(Tri), sizeof r);
    mesh.triangles[start[static_cast<std::size_t>(r[0])]++] = r;
  }
  tris = {};
  // A bucket holds about two triangles (a mesh has twice as many triangles as
  // vertices), all with the same first id: an insertion sort on the other two in
  // place of std::sort's calls for each; std::sort for a large one (a vertex of
  // high degree, as in a fan left unrefined).
  for (std::size_t v = 0; v < nv; ++v) {
    Tri* const first = mesh.triangles.data() + (v ? start[v - 1] : 0);
    Tri* const last = mesh.triangles.data() + start[v];
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
  // Constrained edges: few; a plain sort in canonicalize's order.
  std::sort(edges.begin(), edges.end(), [](const ConstrainedEdge& x, const ConstrainedEdge& y) {
    return std::tie(x.a, x.b, x.segment) < std::tie(y.a, y.b, y.segment);
  });
  mesh.constrained_edges = std::move(edges);
  return mesh;
}

IdLimits& id_limits() {
  static IdLimits limits;
  return limits;
}

void check_capacity(std::int64_t vertices, std::int64_t triangles, std::int64_t steiner) {
  const IdLimits limits = id_limits();
  if (ids_fit(vertices, triangles, limits)) return;
  if (steiner == kInputOnly)
    throw CapacityError(fmt::format(
        "the input outgrows the fast engine: {} vertices, whose triangulation may need {} triangles, where its ids "
        "number at most {} vertices and {} triangles; the reference engine (--engine reference) has no such limit",
        vertices, triangles, limits.vertices, limits.triangles));
  throw CapacityError(fmt::format(
      "the mesh outgrows the fast engine: {} vertices and {} triangles, where its ids number at most {} vertices "
      "and {} triangles; a larger --max-area, or --max-steiner {} to stop before it (exit 3)",
      vertices, triangles, limits.vertices, limits.triangles, steiner));
}

}  // namespace lepp::fast
