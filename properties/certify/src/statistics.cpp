// SPDX-License-Identifier: GPL-3.0-or-later
// The statistics of a certified mesh (Report::stats): sizes, angles, edges, the mean Lepp size.
#include "lepp/stats.h"
#include "passes.h"

namespace lepp::certify::pass {
namespace {

double average_lepp_size(const MeshIndex& ix) {
  std::size_t total = 0, count = 0;
  for (std::size_t t = 0; t < ix.mesh.triangles.size(); ++t) {
    if (!ix.tri_ok[t]) continue;
    ++count;
    std::size_t cur = t, size = 1;
    while (size <= ix.mesh.triangles.size()) {
      const int h = ix.longest_half(cur), g = ix.twin[static_cast<std::size_t>(h)];
      if (g < 0 || ix.constrained_half[static_cast<std::size_t>(h)]) break;  // constrained or boundary terminal edge
      const std::size_t next = static_cast<std::size_t>(g / 3);
      ++size;
      if (ix.longest_half(next) == g) break;  // terminal pair: t2 counted
      cur = next;
    }
    total += size;
  }
  return count ? static_cast<double>(total) / static_cast<double>(count) : 0;
}

}  // namespace

void statistics(Certification& cert) {
  const MeshIndex& ix = cert.index;
  Statistics& s = cert.report.stats;
  Mesh valid;
  valid.vertices = ix.mesh.vertices;
  for (std::size_t t = 0; t < ix.mesh.triangles.size(); ++t)
    if (ix.tri_ok[t]) valid.triangles.push_back(ix.T(t));
  const MeshStats m = mesh_stats(valid, ix.pslg);
  s.vertices = ix.mesh.vertices.size();
  s.triangles = ix.mesh.triangles.size();
  s.edges = ix.edges.size();
  s.min_angle_deg = m.min_angle_deg;
  s.avg_min_angle_deg = m.avg_min_angle_deg;
  s.min_area_quality = m.min_area_quality;
  s.shortest_edge = m.shortest_edge;
  s.shortest_edge_ratio = m.shortest_edge_ratio;
  s.avg_lepp_size = average_lepp_size(ix);
}

}  // namespace lepp::certify::pass
