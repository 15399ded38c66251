// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind mesh_checks.h: simple exact checks of a refined mesh, for the
// reference engine's tests.
#include "mesh_checks.h"

#include <gmpxx.h>

#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include <fmt/format.h>

#include "lepp/angle.h"

namespace lepp::reference::testing {

namespace {

struct Q {
  mpq_class x, y;
};
Q q(const Point& p) { return {mpq_class(p.x), mpq_class(p.y)}; }
mpq_class cross(const Q& o, const Q& a, const Q& b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }
mpq_class dot(const Q& o, const Q& a, const Q& b) { return (a.x - o.x) * (b.x - o.x) + (a.y - o.y) * (b.y - o.y); }
mpq_class len2(const Q& a, const Q& b) { return dot(a, b, b); }
std::string tri(const Tri& t) { return fmt::format("({},{},{})", t[0], t[1], t[2]); }
Tri sorted(Tri t) {
  std::sort(t.begin(), t.end());
  return t;
}

}  // namespace

std::string check_min_angle(const Mesh& mesh, double theta_deg, const std::vector<Tri>& except) {
  mpq_class s(engine_sin2_threshold(theta_deg));
  std::set<Tri> skip;
  for (const Tri& t : except) skip.insert(sorted(t));
  for (const Tri& t : mesh.triangles) {
    if (skip.count(sorted(t))) continue;
    for (int k = 0; k < 3; ++k) {
      Q o = q(mesh.vertices[t[k]]), a = q(mesh.vertices[t[(k + 1) % 3]]), b = q(mesh.vertices[t[(k + 2) % 3]]);
      mpq_class c = cross(o, a, b);
      // An obtuse or right angle is >= 90 > theta; an acute one is below theta iff sin^2 < S.
      if (dot(o, a, b) > 0 && c * c < s * len2(o, a) * len2(o, b))
        return fmt::format("triangle {} has an angle below {} degrees at vertex {}", tri(t), theta_deg, t[k]);
    }
  }
  return "";
}

std::string check_input_vertices(const Mesh& mesh, const Pslg& input) {
  if (mesh.input_vertices != input.vertices.size() || mesh.vertices.size() < input.vertices.size())
    return fmt::format("input_vertices is {}, the input has {}", mesh.input_vertices, input.vertices.size());
  for (std::size_t i = 0; i < input.vertices.size(); ++i)
    if (mesh.vertices[i] != input.vertices[i]) return fmt::format("input vertex {} moved", i);
  std::set<int> used;
  for (const Tri& t : mesh.triangles) used.insert(t.begin(), t.end());
  for (const Segment& s : input.segments)
    for (int v : {s.a, s.b})
      if (!used.count(v)) return fmt::format("input vertex {} (a segment endpoint) is in no triangle", v);
  return "";
}

std::string check_segment_chains(const Mesh& mesh, const Pslg& input) {
  std::map<int, std::multimap<int, int>> adjacency;  // segment -> vertex -> neighbours along it
  for (const ConstrainedEdge& e : mesh.constrained_edges) {
    if (e.segment < 0 || e.segment >= static_cast<int>(input.segments.size()))
      return fmt::format("constrained edge ({},{}) has segment id {}", e.a, e.b, e.segment);
    adjacency[e.segment].insert({e.a, e.b});
    adjacency[e.segment].insert({e.b, e.a});
  }
  for (std::size_t s = 0; s < input.segments.size(); ++s) {
    const auto& adj = adjacency[static_cast<int>(s)];
    int from = input.segments[s].a, to = input.segments[s].b, prev = -1, at = from;
    std::size_t steps = 0;
    while (at != to) {
      // Interior vertices of the chain have exactly two neighbours, the ends one.
      std::size_t degree = adj.count(at);
      if (degree != (at == from ? 1u : 2u)) return fmt::format("segment {} is not a chain at vertex {}", s, at);
      auto range = adj.equal_range(at);
      int next = range.first->second == prev ? std::next(range.first)->second : range.first->second;
      prev = at, at = next;
      if (++steps > adj.size()) return fmt::format("segment {} chain loops", s);
    }
    if (adj.count(to) != 1 || 2 * steps != adj.size())
      return fmt::format("segment {} has constrained edges off its chain", s);
  }
  return "";
}

std::string check_locally_delaunay(const Mesh& mesh) {
  std::set<std::pair<int, int>> constrained;
  for (const ConstrainedEdge& e : mesh.constrained_edges) constrained.insert(std::minmax(e.a, e.b));
  std::map<std::pair<int, int>, int> apex_of;  // directed edge a->b -> apex of the triangle left of it
  for (const Tri& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) apex_of[{t[k], t[(k + 1) % 3]}] = t[(k + 2) % 3];
  for (const auto& [edge, c] : apex_of) {
    auto twin = apex_of.find({edge.second, edge.first});
    if (twin == apex_of.end() || constrained.count(std::minmax(edge.first, edge.second))) continue;
    Q a = q(mesh.vertices[edge.first]), b = q(mesh.vertices[edge.second]), qc = q(mesh.vertices[c]),
      d = q(mesh.vertices[twin->second]);
    // In-circle determinant of (a, b, c) counter-clockwise and d.
    mpq_class adx = a.x - d.x, ady = a.y - d.y, bdx = b.x - d.x, bdy = b.y - d.y, cdx = qc.x - d.x, cdy = qc.y - d.y;
    mpq_class det = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) - (bdx * bdx + bdy * bdy) * (adx * cdy - cdx * ady) +
                    (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
    if (det > 0) return fmt::format("edge ({},{}) is not locally Delaunay", edge.first, edge.second);
  }
  return "";
}

std::string check_ccw(const Mesh& mesh) {
  for (const Tri& t : mesh.triangles)
    if (cross(q(mesh.vertices[t[0]]), q(mesh.vertices[t[1]]), q(mesh.vertices[t[2]])) <= 0)
      return fmt::format("triangle {} is not counter-clockwise", tri(t));
  return "";
}

std::string check_max_area(const Mesh& mesh, double max_area) {
  mpq_class limit = 2 * mpq_class(max_area);
  for (const Tri& t : mesh.triangles)
    if (abs(cross(q(mesh.vertices[t[0]]), q(mesh.vertices[t[1]]), q(mesh.vertices[t[2]]))) > limit)
      return fmt::format("triangle {} is larger than {}", tri(t), max_area);
  return "";
}

int orientation(const Point& a, const Point& b, const Point& c) { return sgn(cross(q(a), q(b), q(c))); }

double twice_area(const Mesh& mesh) {
  mpq_class sum = 0;
  for (const Tri& t : mesh.triangles) sum += cross(q(mesh.vertices[t[0]]), q(mesh.vertices[t[1]]), q(mesh.vertices[t[2]]));
  return sum.get_d();
}

}  // namespace lepp::reference::testing
