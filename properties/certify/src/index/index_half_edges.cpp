// SPDX-License-Identifier: GPL-3.0-or-later
// The mesh index's second layer: paired half-edges, merged duplicate vertices.
#include <algorithm>
#include <utility>
#include <unordered_set>

#include "../passes.h"
#include "../point_table.h"
#include "../prefetch.h"
#include "../ranges.h"

namespace lepp::certify::pass {

void index_half_edges(Certification& cert) {
  MeshIndex& ix = cert.index;
  using Half = MeshIndex::Half;
  // The half-edges grouped by edge, in the order of edge_key (smaller end, then larger),
  // each group's half-edges by id: bucketed by their smaller end (a counting sort, in
  // half-edge order), then each bucket, a vertex's few edges, sorted by the larger end.
  // The same order as a sort of (key, id), in linear time. With threads, each range of
  // triangles counts and places its own half-edges (a bucket holds range 0's, then range
  // 1's, ..., so still by id), then each range of smaller ends (ranges of about as many
  // half-edges each) sorts and pairs its buckets alone; the edges and violations merge in
  // range order. Each step's scattered reads and writes (counts, bucket slots, twins) are
  // asked for a few triangles or half-edges ahead (prefetch.h): at 10^7 triangles nearly
  // every one is a cache miss.
  const std::size_t nv = ix.mesh.vertices.size(), nt = ix.mesh.triangles.size();
  const std::vector<std::size_t> tri_ranges = even_ranges(nt, thread_count(cert, nt));  // one a thread: each keeps nv counts
  std::vector<std::vector<int>> next(tri_ranges.size() - 1);  // per range of triangles: counts per smaller end, then where its next half goes
  // The two smaller ends of triangle t's three edges (its smallest vertex is the smaller end of two).
  auto smaller_ends = [&ix](std::size_t t) {
    const Tri& x = ix.T(t);
    const int lo = std::min({x[0], x[1], x[2]}), mid = std::max(std::min(x[0], x[1]), std::min(std::max(x[0], x[1]), x[2]));
    return std::array<std::size_t, 2>{static_cast<std::size_t>(lo), static_cast<std::size_t>(mid)};
  };
  auto each_half = [&ix](std::size_t t, auto&& f) {
    const Tri& x = ix.T(t);
    for (std::size_t i = 0; i < 3; ++i) f(static_cast<int>(3 * t + i), x[i], x[(i + 1) % 3]);
  };
  over_bounds(cert, tri_ranges, [&](std::size_t begin, std::size_t end, RangeFindings& found) {
    std::vector<int>& count = next[found.range];
    count.assign(nv, 0);
    for (std::size_t t = begin; t < end; ++t) {
      if (t + kAhead < end && ix.tri_ok[t + kAhead])
        for (std::size_t v : smaller_ends(t + kAhead)) prefetch_write(&count[v]);
      if (ix.tri_ok[t]) each_half(t, [&](int, int a, int b) { ++count[static_cast<std::size_t>(std::min(a, b))]; });
    }
  });
  ix.half_begin.assign(nv + 1, 0);
  for (std::size_t v = 0, at = 0; v < nv; ++v) {
    ix.half_begin[v] = static_cast<int>(at);
    for (std::vector<int>& count : next) at += static_cast<std::size_t>(std::exchange(count[v], static_cast<int>(at)));
    ix.half_begin[v + 1] = static_cast<int>(at);
  }
  ix.halves.resize(static_cast<std::size_t>(ix.half_begin[nv]));
  // Not written here (UnwrittenVector): the ranges below write every twin, an invalid
  // triangle's -1 while placing, the others' while pairing. At 10^7 triangles a
  // fill on one thread first took as long as the pairing's two ranges.
  ix.twin.resize(nt * 3);
  over_bounds(cert, tri_ranges, [&](std::size_t begin, std::size_t end, RangeFindings& found) {
    std::vector<int>& at = next[found.range];
    for (std::size_t t = begin; t < end; ++t) {
      if (!ix.tri_ok[t]) ix.twin[3 * t] = ix.twin[3 * t + 1] = ix.twin[3 * t + 2] = -1;
      if (t + kAhead < end && ix.tri_ok[t + kAhead])
        for (std::size_t v : smaller_ends(t + kAhead)) prefetch_write(&at[v]);
      if (t + kAhead / 2 < end && ix.tri_ok[t + kAhead / 2])  // its slots, where those counts now point
        for (std::size_t v : smaller_ends(t + kAhead / 2)) prefetch_write(&ix.halves[static_cast<std::size_t>(at[v])]);
      if (ix.tri_ok[t])
        each_half(t, [&](int h, int a, int b) { ix.halves[static_cast<std::size_t>(at[static_cast<std::size_t>(std::min(a, b))]++)] = Half(std::max(a, b), h, a < b); });
    }
  });
  next.clear();
  // counters: [0] edges.
  ix.edge_count = over_bounds(cert, vertex_ranges_by_halves(cert), [&](std::size_t begin, std::size_t end, RangeFindings& found) {
    // Stable (ids stay increasing within an edge): insertion for a vertex's usual few
    // edges, the library's merge sort for a vertex of high degree (a fan's centre).
    auto by_other = [](const Half& x, const Half& y) { return x.other < y.other; };
    const std::size_t first_half = static_cast<std::size_t>(ix.half_begin[begin]), end_half = static_cast<std::size_t>(ix.half_begin[end]);
    std::size_t asked = first_half;  // the twins of the halves before it are asked for
    for (std::size_t v = begin; v < end; ++v) {
      const auto first = ix.halves.begin() + ix.half_begin[v], last = ix.halves.begin() + ix.half_begin[v + 1];
      for (const std::size_t until = std::min(static_cast<std::size_t>(ix.half_begin[v + 1]) + kAhead, end_half); asked < until; ++asked)
        prefetch_write(&ix.twin[static_cast<std::size_t>(ix.halves[asked].h())]);
      if (last - first > 32) {
        std::stable_sort(first, last, by_other);
      } else {
        for (auto it = first; it != last; ++it)
          for (auto k = it; k != first && by_other(*k, *(k - 1)); --k) std::iter_swap(k, k - 1);
      }
      const int lo = static_cast<int>(v);
      for (auto i = first; i != last;) {
        auto j = i;
        while (j != last && j->other == i->other) ++j;
        const int hi = i->other;
        ++found.counters[0];
        if (j - i > 2) {
          const int a = i->up() ? lo : hi, b = i->up() ? hi : lo;  // the first half-edge's way
          Violation bad{Reason::EdgeOverused,
                        fmt::format("edge {}-{} {} {} lies in {} triangles (overlap)", a, b, pt(ix.P(a)), pt(ix.P(b)), j - i), {}, {{a, b}},
                        {a, b}, {}, -1};
          for (auto k = i; k != j; ++k) {
            bad.triangles.push_back(k->h() / 3);
            ix.twin[static_cast<std::size_t>(k->h())] = -2;
          }
          found.add(std::move(bad));
        } else if (j - i == 2) {
          const int h0 = i->h(), h1 = (i + 1)->h();
          if (i->up() == (i + 1)->up()) {
            const int a = i->up() ? lo : hi, b = i->up() ? hi : lo;
            found.add({Reason::EdgeSameDirection,
                       fmt::format("edge {}-{} {} {} is traversed the same way by triangles {} and {} (overlap or fold)", a, b,
                                   pt(ix.P(a)), pt(ix.P(b)), h0 / 3, h1 / 3),
                       {h0 / 3, h1 / 3}, {{a, b}}, {a, b}, {}, -1});
            ix.twin[static_cast<std::size_t>(h0)] = ix.twin[static_cast<std::size_t>(h1)] = -2;
          } else {
            ix.twin[static_cast<std::size_t>(h0)] = h1;
            ix.twin[static_cast<std::size_t>(h1)] = h0;
          }
        } else {
          ix.twin[static_cast<std::size_t>(i->h())] = -1;  // a boundary edge
        }
        i = j;
      }
    }
  })[0];
}

namespace {

// Whether two finite points are equal (as Point's == compares: -0 is 0).
bool any_duplicate_point(const std::vector<Point>& points) {
  PointTable table(points.size());
  auto point_of = [&](int i) -> const Point& { return points[static_cast<std::size_t>(i)]; };
  for (std::size_t i = 0; i < points.size(); ++i) {
    // The slot a point kAhead on starts at (scattered over the table: a cache miss each), asked for now.
    if (i + kAhead < points.size()) prefetch_write(table.home_slot(points[i + kAhead]));
    const Point& p = points[i];
    if (!finite(p)) continue;  // NaN is equal to nothing; the sort below skips it too
    int& slot = table.slot(p, point_of);
    if (slot >= 0) return true;
    slot = static_cast<int>(i);
  }
  return false;
}

}  // namespace

// Mesh vertices with the same coordinates are a violation, except an exact
// duplicate of an input vertex that no triangle uses: Triangle keeps an input's
// repeated vertex in its .node, unused, and meshes with one copy (as lepp's
// validate merges it). Such a copy is merged into the one in use, with a warning.
void merge_duplicate_vertices(Certification& cert) {
  MeshIndex& ix = cert.index;
  ix.merged.assign(ix.mesh.vertices.size(), 0);
  if (!any_duplicate_point(ix.mesh.vertices)) return;  // the usual case, in linear time: nothing to merge or report
  std::vector<int> order;
  for (std::size_t i = 0; i < ix.mesh.vertices.size(); ++i)
    if (finite(ix.mesh.vertices[i])) order.push_back(static_cast<int>(i));  // NaN breaks the sort's order
  auto less = [&](int a, int b) { return ix.P(a).x < ix.P(b).x || (ix.P(a).x == ix.P(b).x && ix.P(a).y < ix.P(b).y); };
  std::sort(order.begin(), order.end(), less);
  std::unordered_set<Point, PointHash> input(ix.pslg.vertices.begin(), ix.pslg.vertices.end());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i + 1;
    while (j < order.size() && ix.P(order[j]) == ix.P(order[i])) ++j;
    std::size_t in_use = 0;
    for (std::size_t k = i; k < j; ++k) in_use += ix.used[static_cast<std::size_t>(order[k])];
    if (j - i > 1 && in_use <= 1 && input.count(ix.P(order[i]))) {
      // The copy the triangles use (else the first) stands for the input vertex.
      int kept = order[i];
      for (std::size_t k = i; k < j; ++k)
        if (ix.used[static_cast<std::size_t>(order[k])]) kept = order[k];
      for (std::size_t k = i; k < j; ++k)
        if (order[k] != kept) {
          ix.merged[static_cast<std::size_t>(order[k])] = 1;
          cert.report.warnings.push_back(fmt::format("mesh vertex {} duplicates mesh vertex {} {}, an input vertex, and is in no triangle; merged",
                                                 order[k], kept, pt(ix.P(kept))));
        }
    } else {
      for (std::size_t k = i + 1; k < j; ++k)
        cert.add({Reason::DuplicateMeshVertex,
                  fmt::format("mesh vertices {} and {} have the same coordinates {}", order[k - 1], order[k], pt(ix.P(order[k]))), {}, {},
                  {order[k - 1], order[k]}, {}, -1});
    }
    i = j;
  }
}

}  // namespace lepp::certify::pass
