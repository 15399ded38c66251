// SPDX-License-Identifier: GPL-3.0-or-later
// The constrained-edge checks on the built index: split points on their segment, listed edges on chains.
#include "../index/chain_predicates.h"
#include "../passes.h"
#include "lepp/certify/checks.h"

namespace lepp::certify {
namespace pass {

// Where validate() split a file's segment (at a vertex on it, or with
// --split-crossings at a crossing rounded to doubles), the pieces must stay
// on that segment: each joint within the chain tolerance of the line through
// the segment's ends (segment_tolerance with the joints as interior
// vertices). A rounded crossing is within half an ulp per coordinate.
void check_split_points(Certification& cert) {
  const MeshIndex& ix = cert.index;
  const std::vector<int>& origin = ix.pslg.segment_origin;
  if (origin.size() != ix.pslg.segments.size()) return;
  for (std::size_t first = 0; first < origin.size();) {
    std::size_t last = first;
    while (last + 1 < origin.size() && origin[last + 1] == origin[first]) ++last;
    if (last > first) {
      const int a = ix.input_to_mesh[static_cast<std::size_t>(ix.pslg.segments[first].a)];
      const int b = ix.input_to_mesh[static_cast<std::size_t>(ix.pslg.segments[last].b)];
      if (a >= 0 && b >= 0) {
        const double tol = segment_tolerance(ix.P(a), ix.P(b), last - first);
        for (std::size_t k = first; k < last; ++k) {
          const int v = ix.input_to_mesh[static_cast<std::size_t>(ix.pslg.segments[k].b)];
          if (v < 0 || within(ix.P(a), ix.P(b), ix.P(v), tol)) continue;
          cert.add({Reason::SteinerOffSegment,
                    fmt::format("vertex {} {} where segment {} of the input was split is off it ({} {}) by more than the "
                                "tolerance {} per coordinate",
                                v, pt(ix.P(v)), origin[first] + 1, pt(ix.P(a)), pt(ix.P(b)), tol),
                    {}, {}, {v, a, b}, {}, static_cast<int>(k)});
        }
      }
    }
    first = last + 1;
  }
}

void check_listed_constrained_edges(Certification& cert) {
  const MeshIndex& ix = cert.index;
  for (const ConstrainedEdge& e : ix.mesh.constrained_edges) {
    auto it = ix.chain_edge.find(edge_key(e.a, e.b));
    const bool ids = e.a >= 0 && e.b >= 0 && static_cast<std::size_t>(e.a) < ix.mesh.vertices.size() &&
                     static_cast<std::size_t>(e.b) < ix.mesh.vertices.size();
    if (it == ix.chain_edge.end()) {
      cert.add({Reason::ConstrainedEdgeNotOnSegment,
                ids ? fmt::format("listed constrained edge {}-{} {} {} is on no input segment's chain", e.a, e.b, pt(ix.P(e.a)), pt(ix.P(e.b)))
                    : fmt::format("listed constrained edge {}-{} has a vertex id out of range", e.a, e.b),
                {}, {{e.a, e.b}}, ids ? std::vector<int>{e.a, e.b} : std::vector<int>{}, {}, e.segment});
    } else if (e.segment >= 0 && e.segment != it->second) {
      cert.add({Reason::ConstrainedEdgeWrongSegment,
                fmt::format("constrained edge {}-{} is tagged segment {} but lies on segment {}", e.a, e.b, e.segment, it->second), {},
                {{e.a, e.b}}, {e.a, e.b}, {}, it->second});
    }
  }
  if (ix.mesh.constrained_edges.empty()) return;  // the mesh lists none: found by geometry only
  for (const auto& [key, s] : ix.chain_edge)
    if (!ix.listed.count(key)) {
      const auto [a, b] = edge_ends(key);
      cert.add({Reason::ConstrainedEdgeUnlisted,
                fmt::format("edge {}-{} {} {} lies on segment {} but the mesh does not list it as constrained", a, b, pt(ix.P(a)), pt(ix.P(b)), s),
                {}, {{a, b}}, {a, b}, {}, s});
    }
}

void constraints(Certification& cert) {
  check_split_points(cert);
  check_listed_constrained_edges(cert);
}

}  // namespace pass

Report check_constraints(const Pslg& pslg, const Mesh& mesh, const Options& options) {
  return pass::run_alone(Check::Constraints, pass::constraints, pslg, mesh, options);
}

}  // namespace lepp::certify
