// SPDX-License-Identifier: GPL-3.0-or-later
// The size-bound check on the built index: regions flooded from their points, each area against its bound.
#include <algorithm>
#include <cmath>

#include "../exact.h"
#include "../passes.h"
#include "../ranges.h"
#include "lepp/certify/checks.h"

namespace lepp::certify {
namespace pass {
namespace {

// The lowest-index CCW triangle whose closed interior holds q, and how many of its
// edges q lies on; triangle -1 when none holds it (a gap, reported elsewhere).
struct Location {
  int triangle = -1;
  int zeros = 0;    // 0 strictly inside, 1 on an edge, 2 at a vertex
  int corner = -1;  // on an edge: its half-edge index i (T[i] -> T[i+1]); at a vertex: the vertex's index i
};
Location locate(const MeshIndex& ix, const Point& q) {
  for (std::size_t t = 0; t < ix.mesh.triangles.size(); ++t) {
    if (!ix.tri_ok[t]) continue;
    const Tri& x = ix.T(t);
    const Point &a = ix.P(x[0]), &b = ix.P(x[1]), &c = ix.P(x[2]);
    if (q.x < std::min({a.x, b.x, c.x}) || q.x > std::max({a.x, b.x, c.x}) || q.y < std::min({a.y, b.y, c.y}) ||
        q.y > std::max({a.y, b.y, c.y}))
      continue;
    if (exact::orient(a, b, c) <= 0) continue;
    std::array<int, 3> o{};
    bool inside = true;
    for (int i = 0; i < 3 && inside; ++i) {
      o[static_cast<std::size_t>(i)] = exact::orient(ix.P(x[static_cast<std::size_t>(i)]), ix.P(x[static_cast<std::size_t>((i + 1) % 3)]), q);
      inside = o[static_cast<std::size_t>(i)] >= 0;
    }
    if (!inside) continue;
    Location l{static_cast<int>(t), 0, -1};
    for (int i = 0; i < 3; ++i)
      if (o[static_cast<std::size_t>(i)] == 0) ++l.zeros;
    if (l.zeros == 1) {
      for (int i = 0; i < 3; ++i)
        if (o[static_cast<std::size_t>(i)] == 0) l.corner = i;
    } else if (l.zeros == 2) {
      // Edges i and i+1 meet at vertex i+1 (edge i runs T[i] -> T[i+1]).
      for (int i = 0; i < 3; ++i)
        if (o[static_cast<std::size_t>(i)] == 0 && o[static_cast<std::size_t>((i + 1) % 3)] == 0) l.corner = (i + 1) % 3;
    }
    return l;
  }
  return {};
}

// The half-edge x -> y of a valid triangle, or -1.
int half_edge(const MeshIndex& ix, int x, int y) {
  for (std::size_t h = 0; h < ix.twin.size(); ++h)
    if (ix.tri_ok[h / 3] && ix.from(static_cast<int>(h)) == x && ix.to(static_cast<int>(h)) == y) return static_cast<int>(h);
  return -1;
}

// A region point the mesh puts on a chain of segment s (at its vertex v, or on its
// edge from chain[k] to chain[k + 1]) while the input has it off the segment (a chain
// vertex rounded off the line): the triangle on the point's side of the segment.
int seed_beside_chain(const MeshIndex& ix, int s, std::size_t k, const Point& q) {
  const Segment& seg = ix.pslg.segments[static_cast<std::size_t>(s)];
  const int side = exact::orient(ix.pslg.vertices[static_cast<std::size_t>(seg.a)], ix.pslg.vertices[static_cast<std::size_t>(seg.b)], q);
  const std::vector<int>& chain = ix.chains[static_cast<std::size_t>(s)];
  if (side == 0 || k + 1 >= chain.size()) return -1;
  // Half-edge x -> y has its triangle on its left: the left side of a -> b.
  const int h = side > 0 ? half_edge(ix, chain[k], chain[k + 1]) : half_edge(ix, chain[k + 1], chain[k]);
  return h < 0 ? -1 : h / 3;
}

// The triangles a region point floods from (docs/CERTIFIER.md section 7).
std::vector<int> region_seeds(const MeshIndex& ix, const Point& q) {
  const Location l = locate(ix, q);
  if (l.triangle < 0) return {};
  const Tri& x = ix.T(static_cast<std::size_t>(l.triangle));
  if (l.zeros == 1) {
    const int a = x[static_cast<std::size_t>(l.corner)], b = x[static_cast<std::size_t>((l.corner + 1) % 3)];
    auto it = ix.chain_edge.find(edge_key(a, b));
    if (it == ix.chain_edge.end()) return {l.triangle};  // an unconstrained edge: the flood crosses it
    const std::vector<int>& chain = ix.chains[static_cast<std::size_t>(it->second)];
    for (std::size_t k = 0; k + 1 < chain.size(); ++k)
      if (edge_key(chain[k], chain[k + 1]) == it->first) {
        const int seed = seed_beside_chain(ix, it->second, k, q);
        return seed < 0 ? std::vector<int>{} : std::vector<int>{seed};
      }
    return {};
  }
  if (l.zeros == 2) {
    const int v = x[static_cast<std::size_t>(l.corner)];
    if (ix.mesh_to_input[static_cast<std::size_t>(v)] >= 0) return {};  // an input vertex: nothing (and see InputVertexMoved)
    const int s = ix.vertex_segment[static_cast<std::size_t>(v)];
    if (s >= 0) {
      const std::vector<int>& chain = ix.chains[static_cast<std::size_t>(s)];
      const std::size_t k = static_cast<std::size_t>(std::find(chain.begin(), chain.end(), v) - chain.begin());
      const int seed = seed_beside_chain(ix, s, k, q);
      return seed < 0 ? std::vector<int>{} : std::vector<int>{seed};
    }
    std::vector<int> fan;  // a Steiner vertex off every segment: its triangles, one region
    for (std::size_t t = 0; t < ix.mesh.triangles.size(); ++t)
      if (ix.tri_ok[t] && (ix.T(t)[0] == v || ix.T(t)[1] == v || ix.T(t)[2] == v)) fan.push_back(static_cast<int>(t));
    return fan;
  }
  return {l.triangle};
}

// Each region point, in file order, floods the mesh across edges on no segment chain,
// overwriting earlier regions (Triangle's order, ALGORITHM.md section 2).
void assign_regions(Certification& cert) {
  const MeshIndex& ix = cert.index;
  const std::size_t n = ix.pslg.regions.size();
  cert.report.region_places = ix.domain.region_places;
  cert.report.triangle_region.assign(ix.mesh.triangles.size(), -1);
  std::vector<int> stamp(ix.mesh.triangles.size(), -1);
  for (std::size_t r = 0; r < n; ++r) {
    if (ix.domain.region_places[r] != RegionPlace::Floods) continue;
    std::vector<int> todo = region_seeds(ix, ix.pslg.regions[r].at);
    for (int t : todo) stamp[static_cast<std::size_t>(t)] = static_cast<int>(r);
    while (!todo.empty()) {
      const int t = todo.back();
      todo.pop_back();
      cert.report.triangle_region[static_cast<std::size_t>(t)] = static_cast<int>(r);
      for (int i = 0; i < 3; ++i) {
        const std::size_t h = static_cast<std::size_t>(3 * t + i);
        const int g = ix.twin[h];
        if (g < 0 || ix.constrained_half[h] || stamp[static_cast<std::size_t>(g / 3)] == static_cast<int>(r)) continue;
        stamp[static_cast<std::size_t>(g / 3)] = static_cast<int>(r);
        todo.push_back(g / 3);
      }
    }
  }
  cert.report.region_triangles.assign(n, 0);
  for (int r : cert.report.triangle_region)
    if (r >= 0) ++cert.report.region_triangles[static_cast<std::size_t>(r)];
}

bool is_bound(double b) { return b > 0 && std::isfinite(b); }

// |orient(a, b, c)| > 2 * bound, exactly: the doubled area against twice the bound.
bool area_above(const Point& a, const Point& b, const Point& c, double bound) {
  return exact::sign([&](auto z) -> decltype(z) {
           using NT = decltype(z);
           NT det = (NT(b.x) - NT(a.x)) * (NT(c.y) - NT(a.y)) - (NT(b.y) - NT(a.y)) * (NT(c.x) - NT(a.x));
           return CGAL::abs(det) - (NT(bound) + NT(bound));
         }) > 0;
}

std::string region_text(const Pslg& pslg, int r) {
  const std::size_t i = static_cast<std::size_t>(r);
  const int line = i < pslg.region_lines.size() ? pslg.region_lines[i] : 0;
  return line > 0 ? fmt::format("region {} (line {} of {})", r, line, pslg.source.empty() ? "the input" : pslg.source)
                  : fmt::format("region {}", r);
}

// Triangle t's area above `bound`, in region r (-1: none); use_region: the bound is the region's.
Violation area_violation(const Certification& cert, std::size_t t, int r, bool use_region, double bound) {
  const MeshIndex& ix = cert.index;
  const Tri& x = ix.T(t);
  const Point &a = ix.P(x[0]), &b = ix.P(x[1]), &c = ix.P(x[2]);
  const double area = std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) / 2;
  const std::string whose = use_region ? fmt::format("the bound {} of {}", bound, region_text(ix.pslg, r))
                                       : fmt::format("the global bound {} (--max-area){}", bound,
                                                     r >= 0 ? ", in " + region_text(ix.pslg, r)
                                                     : cert.options.region_area_bounds ? std::string(", in no region") : std::string());
  Violation v{Reason::AreaAboveBound,
              fmt::format("{} has area about {}, above {} (exactly: doubled area > 2 x bound)", ix.tri_text(t), area, whose),
              {static_cast<int>(t)}, {}, {x[0], x[1], x[2]}, {}, -1};
  v.region = r;
  return v;
}

void check_area_bounds(Certification& cert) {
  const MeshIndex& ix = cert.index;
  cert.report.max_area = is_bound(cert.options.max_area) ? cert.options.max_area : 0;
  cert.report.region_area_bounds = cert.options.region_area_bounds;
  const double max_area = cert.report.max_area;
  if (ix.area_bound.bound > 0 && ix.area_bound.bound == max_area) {
    // One bound for every valid triangle: the index found those above it (index_triangles).
    cert.report.area_checked += static_cast<std::size_t>(std::count(ix.tri_ok.begin(), ix.tri_ok.end(), 1));
    for (const std::vector<std::size_t>& in_range : ix.area_bound.above)
      for (std::size_t t : in_range) cert.add(area_violation(cert, t, -1, false, max_area));
    return;
  }
  const std::vector<int>& triangle_region = cert.report.triangle_region;
  // Over ranges of triangles (ranges.h); counters: [0] triangles checked.
  const auto counts = over_ranges(cert, ix.mesh.triangles.size(), [&](std::size_t begin, std::size_t end, RangeFindings& found) {
    for (std::size_t t = begin; t < end; ++t) {
      if (!ix.tri_ok[t]) continue;
      const int r = cert.options.region_area_bounds ? triangle_region[t] : -1;
      const double regional = r >= 0 ? ix.pslg.regions[static_cast<std::size_t>(r)].max_area : 0;
      // The smaller bound applies; on a tie, the region's is named.
      const bool use_region = is_bound(regional) && (max_area <= 0 || regional <= max_area);
      const double bound = use_region ? regional : max_area;
      if (bound <= 0) continue;
      ++found.counters[0];
      const Tri& x = ix.T(t);
      if (area_above(ix.P(x[0]), ix.P(x[1]), ix.P(x[2]), bound)) found.add(area_violation(cert, t, r, use_region, bound));
    }
  });
  cert.report.area_checked += counts[0];
}

}  // namespace

void size_bound(Certification& cert) {
  if (cert.options.region_area_bounds) assign_regions(cert);
  if (cert.options.max_area > 0 || cert.options.region_area_bounds) check_area_bounds(cert);
}

}  // namespace pass

Report check_size_bound(const Pslg& pslg, const Mesh& mesh, const Options& options) {
  return pass::run_alone(Check::SizeBound, pass::size_bound, pslg, mesh, options);
}

}  // namespace lepp::certify
