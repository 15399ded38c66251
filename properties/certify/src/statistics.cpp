// SPDX-License-Identifier: GPL-3.0-or-later
// The statistics of a certified mesh (Report::stats): sizes, angles, edges, the mean Lepp size.
#include <algorithm>
#include <array>
#include <unordered_map>
#include <vector>

#include "lepp/stats.h"
#include "passes.h"
#include "prefetch.h"
#include "ranges.h"

namespace lepp::certify::pass {
namespace {

// A walk longer than this many triangles remembers the Lepp sizes of the triangles it
// passes beyond it: Lepp(t) is t followed by Lepp(next) (the paper, section 2), so
// size(c_i) = size(t) - i along a walk c_0 = t, c_1, ... A fan of n triangles whose
// longest edges chain makes n walks of up to n steps (the fuzzers' slowest input spent
// 80 % of its time here); quality meshes' Lepps are a few triangles long and never pay.
constexpr std::size_t kRememberAfter = 16;

// The Lepp sizes of the valid triangles in [begin, end), summed, and how many there are.
// Walks strictly increase the edge order (the next triangle's longest edge is longer than
// the one crossed), so they end; `size <= nt` only guards a broken index.
std::array<std::size_t, 2> lepp_size_sum(const MeshIndex& ix, std::size_t begin, std::size_t end) {
  const std::size_t nt = ix.mesh.triangles.size();
  std::unordered_map<std::size_t, std::size_t> remembered;  // triangle -> its Lepp size
  std::vector<std::size_t> path;                            // the walk's triangles past kRememberAfter
  std::size_t total = 0, count = 0;
  for (std::size_t t = begin; t < end; ++t) {
    if (t + kAhead < end) prefetch_across_longest(ix, t + kAhead);
    if (!ix.tri_ok[t]) continue;
    ++count;
    path.clear();
    std::size_t cur = t, size = 1;
    while (size <= nt) {
      if (size > kRememberAfter) {
        if (const auto known = remembered.find(cur); known != remembered.end()) {
          size += known->second - 1;  // cur is the walk's triangle number size - 1
          break;
        }
        path.push_back(cur);
      }
      const int h = ix.longest_half(cur), g = ix.twin[static_cast<std::size_t>(h)];
      if (g < 0 || ix.constrained_half[static_cast<std::size_t>(h)]) break;  // constrained or boundary terminal edge
      const std::size_t next = static_cast<std::size_t>(g / 3);
      ++size;
      if (ix.longest_half(next) == g) break;  // terminal pair: t2 counted
      cur = next;
    }
    total += size;
    if (size > nt) continue;  // a broken index's walk: remember nothing
    // path[k] is the walk's triangle number kRememberAfter + k (0 is t); the terminal
    // pair's second triangle is not in path, and its own Lepp is the pair, not size 1.
    for (std::size_t k = 0; k < path.size(); ++k) remembered.emplace(path[k], size - kRememberAfter - k);
  }
  return {total, count};
}

// Over ranges of triangles (the sums are integers: the same for any split).
double average_lepp_size(Certification& cert) {
  const MeshIndex& ix = cert.index;
  const auto sums = over_ranges(cert, ix.mesh.triangles.size(),
                                [&](std::size_t begin, std::size_t end, RangeFindings& found) {
                                  found.counters = lepp_size_sum(ix, begin, end);
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
