// SPDX-License-Identifier: GPL-3.0-or-later
// certify(): the passes in the order docs/CERTIFIER.md lists the checks. Every decision
// is an exact sign (exact.h); doubles appear only in messages and statistics.
#include "lepp/certify.h"

#include <algorithm>
#include <cmath>
#include <future>
#include <optional>

#include "lepp/refine.h"
#include "passes.h"

namespace lepp::certify {
namespace pass {

void build_index(Certification& cert) {
  index_triangles(cert);
  index_half_edges(cert);
  index_adjacency(cert);
  merge_duplicate_vertices(cert);
  index_domain(cert);
  index_input_vertices(cert);
  index_chains(cert);
}

Report run_alone(Check group, void (*group_pass)(Certification&), const Pslg& pslg, const Mesh& mesh, const Options& options) {
  Report report;
  Certification cert(pslg, mesh, options, report, group);
  build_index(cert);
  group_pass(cert);
  return report;
}

}  // namespace pass

double segment_tolerance(const Point& a, const Point& b, std::size_t interior_vertices) {
  const double m = std::max({std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y)});
  if (m == 0) return 0;
  int exponent = 0;
  std::frexp(m, &exponent);  // m = f * 2^exponent, f in [0.5, 1): ulp(m) = 2^(exponent - 53)
  const double ulp = std::ldexp(1.0, std::max(exponent - 53, -1074));
  return static_cast<double>(interior_vertices + 1) * ulp;
}

// The index is built as the checks need it, interleaved with them: the report lists
// violations in the order they are found, and that order is part of its output.
Report certify(const Pslg& pslg, const Mesh& mesh, const Options& options) {
  Report report;
  Certification cert(pslg, mesh, options, report);
  // 1. Topology (and the index's half-edges and adjacency), 2. input vertices.
  pass::index_triangles(cert);
  pass::index_half_edges(cert);
  pass::index_adjacency(cert);
  // With threads, the statistics' angles and edges beside the passes that follow (they
  // read only the valid triangles): after the passes above, which use every thread, so
  // that they fill the second one while the steps up to the chains' embedding run on one.
  std::optional<std::future<MeshStats>> stats_ahead;
  if (threads_or_cores(options.threads) > 1)
    stats_ahead = std::async(std::launch::async, [&cert] { return pass::valid_triangle_stats(cert.index); });
  pass::merge_duplicate_vertices(cert);
  pass::index_domain(cert);
  pass::index_input_vertices(cert);
  pass::check_unused_vertices(cert);
  pass::check_outside_vertices_uncovered(cert);
  // 3. Constrained edges (and the index's chains); the coverage checks need the chains.
  pass::index_chains(cert);
  pass::check_split_points(cert);
  pass::check_listed_constrained_edges(cert);
  pass::check_coverage(cert);
  pass::check_chains_cross_nowhere(cert);
  pass::check_euler(cert);
  // 4. Delaunay, 5. minimum angle, 6. Theorem 2, 7. size bounds.
  pass::delaunay(cert);
  pass::min_angle(cert);
  pass::theorem2(cert);
  pass::size_bound(cert);
  pass::statistics(cert, stats_ahead ? &*stats_ahead : nullptr);
  return report;
}

}  // namespace lepp::certify
