// SPDX-License-Identifier: GPL-3.0-or-later
// The Delaunay check on the built index: the in-circle test across every edge it covers.
#include "../exact.h"
#include "../passes.h"
#include "../prefetch.h"
#include "../ranges.h"
#include "lepp/certify/checks.h"

namespace lepp::certify {
namespace pass {

// Every interior edge (constrained ones only when conforming) locally Delaunay, exactly.
void delaunay(Certification& cert) {
  const MeshIndex& ix = cert.index;
  const bool conforming = cert.options.conforming;
  // counters: [0] edges checked, [1] cocircular edges.
  // Over triangles, each one's half-edges in turn: half-edge order, as the report lists them.
  // The apex across each edge is asked for two steps ahead: its triangle 2 kAhead
  // triangles ahead, then, that triangle loaded, its point kAhead ahead (prefetch.h).
  const std::size_t nt = ix.mesh.triangles.size();
  const auto counts = over_ranges(cert, nt, [&](std::size_t begin, std::size_t end, RangeFindings& found) {
    for (std::size_t t = begin; t < end; ++t) {
      if (t + 2 * kAhead < end)
        for (std::size_t i = 0; i < 3; ++i)
          if (const int g = ix.twin[3 * (t + 2 * kAhead) + i]; g >= 0) prefetch(&ix.T(static_cast<std::size_t>(g / 3)));
      if (t + kAhead < end) {
        const std::size_t u = t + kAhead;
        if (ix.ccw[u]) {
          prefetch_points(ix, ix.T(u));
          for (std::size_t i = 0; i < 3; ++i)
            if (const int g = ix.twin[3 * u + i]; g > static_cast<int>(3 * u + i)) prefetch(&ix.P(ix.apex(g)));
        }
      }
      for (std::size_t h = 3 * t; h < 3 * t + 3; ++h) {
        const int g = ix.twin[h];
        if (g < static_cast<int>(h)) continue;  // each interior edge once; boundary and bad edges skipped
        if (ix.constrained_half[h] && !conforming) continue;
        const int a = ix.from(static_cast<int>(h)), b = ix.to(static_cast<int>(h)), c = ix.apex(static_cast<int>(h)), d = ix.apex(g);
        ++found.counters[0];
        if (!ix.ccw[h / 3]) continue;  // reported; in-circle meaningless
        const int side = exact::incircle(ix.P(a), ix.P(b), ix.P(c), ix.P(d));
        if (side == 0) ++found.counters[1];
        if (side > 0)
          found.add({Reason::NotLocallyDelaunay,
                     fmt::format("{}edge {}-{} {} {} is not locally Delaunay: vertex {} {} is strictly inside the circumcircle of {}",
                                 ix.constrained_half[h] ? "constrained " : "", a, b, pt(ix.P(a)), pt(ix.P(b)), d, pt(ix.P(d)),
                                 ix.tri_text(h / 3)),
                     {static_cast<int>(h / 3), g / 3}, {{a, b}}, {a, b, c, d}, {}, -1});
      }
    }
  });
  cert.report.stats.delaunay_edges_checked += counts[0];
  cert.report.stats.cocircular_edges += counts[1];
}

}  // namespace pass

Report check_delaunay(const Pslg& pslg, const Mesh& mesh, const Options& options) {
  return pass::run_alone(Check::Delaunay, pass::delaunay, pslg, mesh, options);
}

}  // namespace lepp::certify
