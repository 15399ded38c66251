// SPDX-License-Identifier: GPL-3.0-or-later
// The topology checks on the built index: unused vertices, coverage of the domain, chains that cross, Euler.
#include <algorithm>
#include <tuple>
#include <unordered_map>

#include "../chain_embedding.h"
#include "../passes.h"
#include "../ranges.h"
#include "lepp/certify/checks.h"

namespace lepp::certify {
namespace pass {

// A Steiner vertex in no triangle (input vertices are the input check's).
void check_unused_vertices(Certification& cert) {
  const MeshIndex& ix = cert.index;
  for (std::size_t v = 0; v < ix.mesh.vertices.size(); ++v) {
    if (ix.used[v] || ix.merged[v]) continue;
    const int in = ix.mesh_to_input[v];
    if (in >= 0 && !ix.domain.vertex_in_domain[static_cast<std::size_t>(in)]) continue;  // outside the domain: may be unused
    if (in >= 0) continue;  // reported as InputVertexMissing
    cert.add({Reason::UnusedVertex, fmt::format("Steiner vertex {} {} is in no triangle", v, pt(ix.P(static_cast<int>(v)))), {}, {},
              {static_cast<int>(v)}, {}, -1});
  }
}

// Coverage: with every triangle CCW and every interior edge used once each way,
// the number of triangles over a point is the winding number of the mesh's
// boundary edges; these checks make that boundary the domain's (docs/CERTIFIER.md).
void check_coverage(Certification& cert) {
  const MeshIndex& ix = cert.index;
  // A boundary half-edge on no chain, in half-edge order over ranges.
  over_ranges(cert, ix.twin.size(), [&](std::size_t begin, std::size_t end, RangeFindings& found) {
    for (std::size_t h = begin; h < end; ++h) {
      if (ix.twin[h] != -1 || !ix.tri_ok[h / 3] || ix.constrained_half[h]) continue;
      const int x = ix.from(static_cast<int>(h)), y = ix.to(static_cast<int>(h));
      found.add({Reason::BoundaryNotOnDomainBoundary,
                 fmt::format("edge {}-{} {} {} of {} has no triangle on its other side but lies on no segment (a gap)", x, y, pt(ix.P(x)),
                             pt(ix.P(y)), ix.tri_text(h / 3)),
                 {static_cast<int>(h / 3)}, {{x, y}}, {x, y}, {}, -1});
    }
  });
  // A chain edge's half-edges (x < y: half x->y, half y->x), the last by id if several.
  auto halves_of_chain = [&ix](int x, int y) {
    std::array<int, 2> pair{-1, -1};
    for (auto [first, last] = ix.halves_on(x, y); first != last; ++first)
      pair[first->up() ? 0 : 1] = first->h();
    return pair;
  };
  for (std::size_t s = 0; s < ix.chains.size(); ++s) {
    const std::vector<int>& chain = ix.chains[s];
    const unsigned char sides = ix.domain.segment_sides[s];
    for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
      const int u = chain[k], w = chain[k + 1];
      const std::array<int, 2> pair = halves_of_chain(u, w);
      const int left = pair[u < w ? 0 : 1], right = pair[u < w ? 1 : 0];  // half u->w has its triangle on the left
      auto side = [&](int half, bool domain, const char* name) {
        if (domain && half < 0)
          cert.add({Reason::DomainBoundaryUncovered,
                    fmt::format("no triangle on the {} of edge {}-{} {} {} of segment {}, a domain side (a gap)", name, u, w, pt(ix.P(u)),
                                pt(ix.P(w)), s),
                    {}, {{u, w}}, {u, w}, {}, static_cast<int>(s)});
        if (!domain && half >= 0)
          cert.add({Reason::MeshOutsideDomain,
                    fmt::format("{} lies on the {} of segment {} edge {}-{}, outside the domain (exterior or hole)", ix.tri_text(half / 3), name,
                                s, u, w),
                    {half / 3}, {{u, w}}, {u, w}, {}, static_cast<int>(s)});
      };
      side(left, sides & ExpectedDomain::Left, "left");
      side(right, sides & ExpectedDomain::Right, "right");
    }
  }
}

// The coverage checks above count triangles by the chains' winding number,
// the domain's only where the chains are drawn as the segments are: no two
// chain edges meet but at a shared endpoint, no mesh vertex lies on one
// (chain_embedding.h). Chains within the tolerance of nearly parallel
// segments can cross where the segments do not.
void check_chains_cross_nowhere(Certification& cert) {
  const MeshIndex& ix = cert.index;
  const std::vector<std::array<int, 2>>& edges = ix.chain_edges;
  std::vector<ChainMeet> meets = chain_meetings(ix.mesh.vertices, edges, ix.used);
  std::sort(meets.begin(), meets.end(), [](const ChainMeet& x, const ChainMeet& y) {
    return std::tie(x.edge, x.other, x.vertex) < std::tie(y.edge, y.other, y.vertex);
  });
  auto text = [&](int i) {
    const auto& e = edges[static_cast<std::size_t>(i)];
    return fmt::format("edge {}-{} {} {} of segment {}", e[0], e[1], pt(ix.P(e[0])), pt(ix.P(e[1])), ix.chain_edge_segment[static_cast<std::size_t>(i)]);
  };
  for (const ChainMeet& m : meets) {
    const auto& e = edges[static_cast<std::size_t>(m.edge)];
    const int s = ix.chain_edge_segment[static_cast<std::size_t>(m.edge)];
    if (m.other >= 0) {
      const auto& f = edges[static_cast<std::size_t>(m.other)];
      cert.add({Reason::ChainEdgesMeet,
                fmt::format("{} and {} meet other than at a shared end: the mesh's boundary crosses itself, so it covers part of the "
                            "plane twice or leaves out domain (a point placed across a nearly parallel segment?)",
                            text(m.edge), text(m.other)),
                {}, {e, f}, {e[0], e[1], f[0], f[1]}, {}, s});
    } else {
      cert.add({Reason::ChainEdgesMeet,
                fmt::format("mesh vertex {} {} lies on {} but is not one of its ends: its triangles overlap the ones along that edge",
                            m.vertex, pt(ix.P(m.vertex)), text(m.edge)),
                {}, {e}, {m.vertex, e[0], e[1]}, {}, s});
    }
  }
}

void check_euler(Certification& cert) {
  const MeshIndex& ix = cert.index;
  long v = 0;
  for (char u : ix.used) v += u;
  std::size_t f = 0;
  for (char ok : ix.tri_ok) f += ok;
  const long euler = v - static_cast<long>(ix.edge_count) + static_cast<long>(f);
  cert.report.stats.euler_mesh = euler;
  cert.report.stats.euler_domain = ix.domain.euler;
  if (euler != ix.domain.euler)
    cert.add({Reason::EulerCharacteristic,
              fmt::format("V - E + F = {} - {} + {} = {}, the domain's is {}", v, ix.edge_count, f, euler, ix.domain.euler), {}, {}, {}, {}, -1});
}

void topology(Certification& cert) {
  check_unused_vertices(cert);
  check_coverage(cert);
  check_chains_cross_nowhere(cert);
  check_euler(cert);
}

}  // namespace pass

Report check_topology(const Pslg& pslg, const Mesh& mesh, const Options& options) {
  return pass::run_alone(Check::Topology, pass::topology, pslg, mesh, options);
}

}  // namespace lepp::certify
