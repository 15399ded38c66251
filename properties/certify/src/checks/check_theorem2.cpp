// SPDX-License-Identifier: GPL-3.0-or-later
// The Theorem 2 check on the built index: no angle over 120 degrees at an unconstrained terminal edge.
#include "../passes.h"
#include "../prefetch.h"
#include "../ranges.h"
#include "lepp/stats.h"
#include "lepp/certify/checks.h"

namespace lepp::certify {
namespace pass {
namespace {

void check_terminal_edges(Certification& cert) {
  const MeshIndex& ix = cert.index;
  // counters: [0] terminal pairs checked.
  const auto counts = over_ranges(cert, ix.mesh.triangles.size(), [&](std::size_t begin, std::size_t end, RangeFindings& found) {
    for (std::size_t t = begin; t < end; ++t) {
      if (t + kAhead < end) prefetch_across_longest(ix, t + kAhead);
      if (!ix.tri_ok[t]) continue;
      const int h = ix.longest_half(t), g = ix.twin[static_cast<std::size_t>(h)];
      if (g < h || ix.constrained_half[static_cast<std::size_t>(h)]) continue;  // once per pair; boundary, bad, constrained skipped
      if (ix.longest_half(static_cast<std::size_t>(g / 3)) != g) continue;       // not terminal
      ++found.counters[0];
      const int a = ix.from(h), b = ix.to(h);
      for (int half : {h, g}) {
        const int c = ix.apex(half);
        if (ix.largest_over_120[static_cast<std::size_t>(half / 3)]) {  // the angle at c (index_triangles: exact::angle_over_120)
          const Point &C = ix.P(c), &A = ix.P(a), &B = ix.P(b);
          const double deg = angle_deg(C, A, B);  // scaled: right at 1e299 and 1e-301 too
          found.add({Reason::TerminalAngleOver120,
                     fmt::format("terminal edge {}-{} {} {} (triangles {} and {}): the angle at {} {} is over 120 degrees (about {})",
                                 a, b, pt(A), pt(B), h / 3, g / 3, c, pt(C), deg),
                     {h / 3, g / 3}, {{a, b}}, {a, b, c}, {}, -1});
        }
      }
    }
  });
  cert.report.stats.terminal_pairs_checked += counts[0];
}

}  // namespace

void theorem2(Certification& cert) {
  if (cert.options.theorem2) check_terminal_edges(cert);
}

}  // namespace pass

Report check_theorem2(const Pslg& pslg, const Mesh& mesh, const Options& options) {
  return pass::run_alone(Check::Theorem2, pass::theorem2, pslg, mesh, options);
}

}  // namespace lepp::certify
