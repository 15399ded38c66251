// SPDX-License-Identifier: GPL-3.0-or-later
// The statistics of a certified mesh (Report::stats): sizes, angles, edges, the mean Lepp size.
#include <algorithm>

#include "lepp/stats.h"
#include "passes.h"
#include "prefetch.h"
#include "ranges.h"

namespace lepp::certify::pass {
namespace {

// Over ranges of triangles (the sums are integers: the same for any split).
double average_lepp_size(Certification& cert) {
  const MeshIndex& ix = cert.index;
  const std::size_t nt = ix.mesh.triangles.size();
  // counters: [0] the Lepps' sizes summed, [1] valid triangles.
  const auto sums = over_ranges(cert, nt, [&](std::size_t begin, std::size_t end, RangeFindings& found) {
    std::size_t total = 0, count = 0;
    for (std::size_t t = begin; t < end; ++t) {
      if (t + kAhead < end) prefetch_across_longest(ix, t + kAhead);
      if (!ix.tri_ok[t]) continue;
      ++count;
      std::size_t cur = t, size = 1;
      while (size <= nt) {
        const int h = ix.longest_half(cur), g = ix.twin[static_cast<std::size_t>(h)];
        if (g < 0 || ix.constrained_half[static_cast<std::size_t>(h)]) break;  // constrained or boundary terminal edge
        const std::size_t next = static_cast<std::size_t>(g / 3);
        ++size;
        if (ix.longest_half(next) == g) break;  // terminal pair: t2 counted
        cur = next;
      }
      total += size;
    }
    found.counters = {total, count};
  });
  return sums[1] ? static_cast<double>(sums[0]) / static_cast<double>(sums[1]) : 0;
}

}  // namespace

MeshStats valid_triangle_stats(const MeshIndex& ix) {
  // The statistics of the valid triangles: the mesh itself when all are (no copy).
  if (std::find(ix.tri_ok.begin(), ix.tri_ok.end(), 0) == ix.tri_ok.end()) return mesh_stats(ix.mesh, ix.pslg);
  Mesh valid;
  valid.vertices = ix.mesh.vertices;
  for (std::size_t t = 0; t < ix.mesh.triangles.size(); ++t)
    if (ix.tri_ok[t]) valid.triangles.push_back(ix.T(t));
  return mesh_stats(valid, ix.pslg);
}

void statistics(Certification& cert, std::future<MeshStats>* ahead) {
  const MeshIndex& ix = cert.index;
  Statistics& s = cert.report.stats;
  const MeshStats m = ahead ? ahead->get() : valid_triangle_stats(ix);
  s.vertices = ix.mesh.vertices.size();
  s.triangles = ix.mesh.triangles.size();
  s.edges = ix.edge_count;
  s.min_angle_deg = m.min_angle_deg;
  s.avg_min_angle_deg = m.avg_min_angle_deg;
  s.min_area_quality = m.min_area_quality;
  s.shortest_edge = m.shortest_edge;
  s.shortest_edge_ratio = m.shortest_edge_ratio;
  s.avg_lepp_size = average_lepp_size(cert);
}

}  // namespace lepp::certify::pass
