// SPDX-License-Identifier: GPL-3.0-or-later
// The mesh index's first layer: valid triangles, paired half-edges, merged duplicate vertices, longest edges.
#include <algorithm>
#include <unordered_set>

#include "../exact.h"
#include "../passes.h"
#include "../ranges.h"

namespace lepp::certify::pass {

void index_triangles(Certification& cert) {
  MeshIndex& ix = cert.index;
  const int n = static_cast<int>(ix.mesh.vertices.size());
  ix.tri_ok.assign(ix.mesh.triangles.size(), 0);
  over_ranges(cert, ix.mesh.triangles.size(), [&](std::size_t begin, std::size_t end, RangeFindings& found) {
    for (std::size_t t = begin; t < end; ++t) {
      const Tri& x = ix.T(t);
      bool ids = true;
      for (int v : x) ids = ids && v >= 0 && v < n;
      if (!ids || x[0] == x[1] || x[1] == x[2] || x[0] == x[2]) {
        found.add({Reason::BadTriangle, fmt::format("triangle {} has vertex ids {} {} {} (out of range or repeated)", t, x[0], x[1], x[2]),
                   {static_cast<int>(t)}, {}, {}, {}, -1});
        continue;
      }
      if (!finite(ix.P(x[0])) || !finite(ix.P(x[1])) || !finite(ix.P(x[2]))) {
        found.add({Reason::BadTriangle, fmt::format("{} has a NaN or infinite coordinate", ix.tri_text(t)), {static_cast<int>(t)}, {}, {}, {}, -1});
        continue;
      }
      ix.tri_ok[t] = 1;  // ranges write apart
      if (exact::orient(ix.P(x[0]), ix.P(x[1]), ix.P(x[2])) <= 0)
        found.add({Reason::NotCounterClockwise, fmt::format("{} is not strictly counter-clockwise", ix.tri_text(t)),
                   {static_cast<int>(t)}, {}, {x[0], x[1], x[2]}, {}, -1});
    }
  });
}

void index_half_edges(Certification& cert) {
  MeshIndex& ix = cert.index;
  // The half-edges grouped by edge, in the order of edge_key (smaller end, then larger),
  // each group's half-edges by id: bucketed by their smaller end (a counting sort, in
  // half-edge order), then each bucket, a vertex's few edges, sorted by the larger end.
  // The same order as a sort of (key, id), in linear time (the sort was a sixth of certify).
  struct Half {
    int other;  // the larger end
    int h;
  };
  const std::size_t nv = ix.mesh.vertices.size();
  std::vector<int> bucket(nv + 1, 0);
  for (std::size_t t = 0; t < ix.mesh.triangles.size(); ++t)
    if (ix.tri_ok[t])
      for (int i = 0; i < 3; ++i) {
        const int h = static_cast<int>(3 * t) + i;
        ++bucket[static_cast<std::size_t>(std::min(ix.from(h), ix.to(h))) + 1];
      }
  for (std::size_t v = 0; v < nv; ++v) bucket[v + 1] += bucket[v];
  std::vector<Half> halves(static_cast<std::size_t>(bucket[nv]));
  {
    std::vector<int> next(bucket.begin(), bucket.end() - 1);
    for (std::size_t t = 0; t < ix.mesh.triangles.size(); ++t)
      if (ix.tri_ok[t])
        for (int i = 0; i < 3; ++i) {
          const int h = static_cast<int>(3 * t) + i, a = ix.from(h), b = ix.to(h);
          halves[static_cast<std::size_t>(next[static_cast<std::size_t>(std::min(a, b))]++)] = {std::max(a, b), h};
        }
  }
  // Stable (ids stay increasing within an edge): insertion for a vertex's usual few
  // edges, the library's merge sort for a vertex of high degree (a fan's centre).
  auto by_other = [](const Half& x, const Half& y) { return x.other < y.other; };
  for (std::size_t v = 0; v < nv; ++v) {
    const auto first = halves.begin() + bucket[v], last = halves.begin() + bucket[v + 1];
    if (last - first > 32) {
      std::stable_sort(first, last, by_other);
      continue;
    }
    for (auto it = first; it != last; ++it)
      for (auto k = it; k != first && by_other(*k, *(k - 1)); --k) std::iter_swap(k, k - 1);
  }
  auto same_edge = [&](std::size_t i, std::size_t j) {
    return halves[i].other == halves[j].other &&
           std::min(ix.from(halves[i].h), ix.to(halves[i].h)) == std::min(ix.from(halves[j].h), ix.to(halves[j].h));
  };
  ix.twin.assign(ix.mesh.triangles.size() * 3, -1);
  ix.used.assign(ix.mesh.vertices.size(), 0);
  ix.edges.reserve(halves.size() / 2 + 1);
  for (std::size_t i = 0; i < halves.size();) {
    std::size_t j = i;
    while (j < halves.size() && same_edge(i, j)) ++j;
    const int a = ix.from(halves[i].h), b = ix.to(halves[i].h);
    ix.edges.push_back({std::min(a, b), std::max(a, b)});
    ix.used[static_cast<std::size_t>(a)] = ix.used[static_cast<std::size_t>(b)] = 1;
    if (j - i > 2) {
      Violation v{Reason::EdgeOverused, fmt::format("edge {}-{} {} {} lies in {} triangles (overlap)", a, b, pt(ix.P(a)), pt(ix.P(b)), j - i),
                  {}, {{a, b}}, {a, b}, {}, -1};
      for (std::size_t k = i; k < j; ++k) {
        v.triangles.push_back(halves[k].h / 3);
        ix.twin[static_cast<std::size_t>(halves[k].h)] = -2;
      }
      cert.add(std::move(v));
    } else if (j - i == 2) {
      const int h0 = halves[i].h, h1 = halves[i + 1].h;
      if (ix.from(h0) == ix.from(h1)) {
        cert.add({Reason::EdgeSameDirection,
                  fmt::format("edge {}-{} {} {} is traversed the same way by triangles {} and {} (overlap or fold)", ix.from(h0), ix.to(h0),
                              pt(ix.P(ix.from(h0))), pt(ix.P(ix.to(h0))), h0 / 3, h1 / 3),
                  {h0 / 3, h1 / 3}, {{ix.from(h0), ix.to(h0)}}, {ix.from(h0), ix.to(h0)}, {}, -1});
        ix.twin[static_cast<std::size_t>(h0)] = ix.twin[static_cast<std::size_t>(h1)] = -2;
      } else {
        ix.twin[static_cast<std::size_t>(h0)] = h1;
        ix.twin[static_cast<std::size_t>(h1)] = h0;
      }
    }
    i = j;
  }
}

// Mesh vertices with the same coordinates are a violation, except an exact
// duplicate of an input vertex that no triangle uses: Triangle keeps an input's
// repeated vertex in its .node, unused, and meshes with one copy (as lepp's
// validate merges it). Such a copy is merged into the one in use, with a warning.
void merge_duplicate_vertices(Certification& cert) {
  MeshIndex& ix = cert.index;
  std::vector<int> order;
  for (std::size_t i = 0; i < ix.mesh.vertices.size(); ++i)
    if (finite(ix.mesh.vertices[i])) order.push_back(static_cast<int>(i));  // NaN breaks the sort's order
  auto less = [&](int a, int b) { return ix.P(a).x < ix.P(b).x || (ix.P(a).x == ix.P(b).x && ix.P(a).y < ix.P(b).y); };
  std::sort(order.begin(), order.end(), less);
  std::unordered_set<Point, PointHash> input(ix.pslg.vertices.begin(), ix.pslg.vertices.end());
  ix.merged.assign(ix.mesh.vertices.size(), 0);
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

void index_longest_edges(Certification& cert) {
  MeshIndex& ix = cert.index;
  ix.longest.assign(ix.mesh.triangles.size(), 0);
  over_ranges(cert, ix.mesh.triangles.size(), [&](std::size_t begin, std::size_t end, RangeFindings&) {
    for (std::size_t t = begin; t < end; ++t) {
      if (!ix.tri_ok[t]) continue;
      int best = 0;
      for (int i = 1; i < 3; ++i) {
        const int h = static_cast<int>(3 * t) + i, b = static_cast<int>(3 * t) + best;
        if (ix.longer(ix.from(h), ix.to(h), ix.from(b), ix.to(b))) best = i;
      }
      ix.longest[t] = static_cast<signed char>(best);  // ranges write apart
    }
  });
}

}  // namespace lepp::certify::pass
