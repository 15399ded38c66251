// SPDX-License-Identifier: GPL-3.0-or-later
// The mesh index's segment layer: vertex adjacency, and each input segment's chain of mesh edges.
#include <algorithm>
#include <utility>

#include "../passes.h"
#include "../prefetch.h"
#include "../ranges.h"
#include "chain_predicates.h"
#include "segment_walk.h"

namespace lepp::certify::pass {
namespace {

// Each vertex's smaller neighbours (its larger ones are its bucket's edges, not copied):
// the buckets' edges (MeshIndex::each_edge's order) placed by their larger end, a
// counting sort. Over ranges of smaller ends, as the half-edge index's pairing: each
// range counts and places its own edges, and a vertex's list holds range 0's, then
// range 1's, ...: ascending, as one pass in edge order makes it. The larger ends are
// scattered (a cache miss each at 10^7 triangles): their counts and slots are asked for
// kAhead halves ahead.
void build_adjacency(Certification& cert) {
  MeshIndex& ix = cert.index;
  const std::vector<MeshIndex::Half>& halves = ix.halves;
  // The larger end of the half-edge `ahead` places on, if there is one.
  auto larger_end = [&halves](std::size_t k, std::size_t ahead) {
    return k + ahead < halves.size() ? static_cast<std::size_t>(halves[k + ahead].other) : 0;
  };
  const std::size_t nv = ix.mesh.vertices.size();
  const std::vector<std::size_t> ranges = vertex_ranges_by_halves(cert);
  std::vector<std::vector<int>> next(ranges.size() - 1);  // per range: counts per larger end, then where its next goes
  over_bounds(cert, ranges, [&](std::size_t begin, std::size_t end, RangeFindings& found) {
    std::vector<int>& count = next[found.range];
    count.assign(nv, 0);
    for (std::size_t a = begin; a < end; ++a)
      ix.each_edge_up_from(a, [&](int b, std::size_t k) {
        prefetch_write(&count[larger_end(k, kAhead)]);
        ++count[static_cast<std::size_t>(b)];
      });
  });
  ix.lower_begin.resize(nv + 1);
  ix.used.resize(nv);
  std::size_t at = 0;
  for (std::size_t v = 0; v < nv; ++v) {
    ix.lower_begin[v] = static_cast<int>(at);
    for (std::vector<int>& count : next) at += static_cast<std::size_t>(std::exchange(count[v], static_cast<int>(at)));
    // In a valid triangle: an end of one of its edges, the smaller (a bucket) or the larger.
    ix.used[v] = ix.half_begin[v + 1] > ix.half_begin[v] || at > static_cast<std::size_t>(ix.lower_begin[v]);
  }
  ix.lower_begin[nv] = static_cast<int>(at);
  ix.lower.resize(at);
  over_bounds(cert, ranges, [&](std::size_t begin, std::size_t end, RangeFindings& found) {
    std::vector<int>& fill = next[found.range];
    for (std::size_t a = begin; a < end; ++a)
      ix.each_edge_up_from(a, [&](int b, std::size_t k) {
        prefetch_write(&fill[larger_end(k, kAhead)]);
        prefetch_write(ix.lower.data() + fill[larger_end(k, kAhead / 2)]);  // may be one past a full list
        ix.lower[static_cast<std::size_t>(fill[static_cast<std::size_t>(b)]++)] = static_cast<int>(a);
      });
  });
  for (const ConstrainedEdge& e : ix.mesh.constrained_edges) ix.listed[edge_key(e.a, e.b)] = e.segment;
}

}  // namespace

void index_adjacency(Certification& cert) { build_adjacency(cert); }

// Each segment's chain of mesh edges (segment_walk.h), its edges and its Steiner vertices.
void index_chains(Certification& cert) {
  MeshIndex& ix = cert.index;
  ix.chains.assign(ix.pslg.segments.size(), {});
  ix.vertex_segment.assign(ix.mesh.vertices.size(), -1);
  ix.constrained_half.assign(ix.mesh.triangles.size() * 3, 0);
  for (std::size_t s = 0; s < ix.pslg.segments.size(); ++s) {
    const int a = ix.input_to_mesh[static_cast<std::size_t>(ix.pslg.segments[s].a)];
    const int b = ix.input_to_mesh[static_cast<std::size_t>(ix.pslg.segments[s].b)];
    const bool in_domain = ix.domain.segment_sides[s] != 0;
    if (a < 0 || b < 0 || !ix.used[static_cast<std::size_t>(a)] || !ix.used[static_cast<std::size_t>(b)]) {
      if (in_domain)
        cert.add({Reason::SegmentMissing, fmt::format("segment {} ({}-{}): an endpoint is not in the mesh", s, ix.pslg.segments[s].a, ix.pslg.segments[s].b),
                  {}, {}, {}, {}, static_cast<int>(s)});
      continue;
    }
    std::vector<int> chain = walk(ix, a, b);
    if (chain.front() == -1) {
      const int stuck = chain.back();
      if (in_domain)
        cert.add({Reason::SegmentMissing,
                  fmt::format("segment {} {}-{} {} {} is not a chain of mesh edges: no edge continues it from vertex {} {}", s, a, b,
                              pt(ix.P(a)), pt(ix.P(b)), stuck, pt(ix.P(stuck))),
                  {}, {}, {a, b, stuck}, {}, static_cast<int>(s)});
      continue;
    }
    const std::size_t interior = chain.size() - 2;
    const double tol = segment_tolerance(ix.P(a), ix.P(b), interior);
    for (std::size_t k = 1; k + 1 < chain.size(); ++k) {
      const int v = chain[k];
      if (!within(ix.P(a), ix.P(b), ix.P(v), tol))
        cert.add({Reason::SteinerOffSegment,
                  fmt::format("vertex {} {} of segment {} {}-{} {} {} is off the segment by more than the tolerance {} per coordinate", v,
                              pt(ix.P(v)), s, a, b, pt(ix.P(a)), pt(ix.P(b)), tol),
                  {}, {}, {v, a, b}, {}, static_cast<int>(s)});
      ix.vertex_segment[static_cast<std::size_t>(v)] = static_cast<int>(s);  // a Steiner point: the walk takes no input vertex
    }
    for (std::size_t k = 0; k + 1 < chain.size(); ++k) ix.chain_edge[edge_key(chain[k], chain[k + 1])] = static_cast<int>(s);
    ix.chains[s] = std::move(chain);
  }
  // The half-edges of valid triangles on chain edges, looked up by edge (not every
  // half-edge looked up in the hash).
  for (const auto& [key, seg] : ix.chain_edge) {
    const std::array<int, 2> e = edge_ends(key);
    for (auto [first, last] = ix.halves_on(e[0], e[1]); first != last; ++first) ix.constrained_half[static_cast<std::size_t>(first->h())] = 1;
  }
  cert.report.stats.constrained_edges = ix.chain_edge.size();
  // Sorted: the checks and reports that scan them do not depend on the hash's order.
  std::vector<std::pair<std::uint64_t, int>> keyed(ix.chain_edge.begin(), ix.chain_edge.end());
  std::sort(keyed.begin(), keyed.end());
  for (const auto& [key, seg] : keyed) {
    const std::array<int, 2> e = edge_ends(key);
    ix.chain_edges.push_back(e);
    ix.chain_edge_segment.push_back(seg);
    ix.chain_segments.segments.push_back({ix.P(e[0]), ix.P(e[1])});
  }
}

}  // namespace lepp::certify::pass
