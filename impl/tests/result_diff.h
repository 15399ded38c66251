// SPDX-License-Identifier: GPL-3.0-or-later
// Comparing two engine runs: the first difference between two results or two
// traces, as a message ("" when they agree). Shared by the differential tests.
#pragma once
#include <string>
#include <vector>

#include <fmt/format.h>

#include "lepp/refine.h"

namespace lepp::impl_test {

inline std::string tri(const Tri& t) { return fmt::format("({} {} {})", t[0], t[1], t[2]); }

// The first difference between two results, or "" when they are the same run.
inline std::string difference(const RefineResult& a, const RefineResult& b) {
  if (a.outcome != b.outcome) return fmt::format("outcome {} vs {}", to_string(a.outcome), to_string(b.outcome));
  if (a.steiner_points != b.steiner_points) return fmt::format("Steiner points {} vs {}", a.steiner_points, b.steiner_points);
  const Mesh &x = a.mesh, &y = b.mesh;
  if (x.vertices.size() != y.vertices.size()) return "vertex counts differ";
  for (std::size_t i = 0; i < x.vertices.size(); ++i)
    if (x.vertices[i] != y.vertices[i])
      return fmt::format("vertex {}: ({:.17g}, {:.17g}) vs ({:.17g}, {:.17g})", i, x.vertices[i].x, x.vertices[i].y,
                         y.vertices[i].x, y.vertices[i].y);
  if (x.triangles.size() != y.triangles.size())
    return fmt::format("{} vs {} triangles", x.triangles.size(), y.triangles.size());
  for (std::size_t i = 0; i < x.triangles.size(); ++i)
    if (x.triangles[i] != y.triangles[i]) return fmt::format("triangle {}: {} vs {}", i, tri(x.triangles[i]), tri(y.triangles[i]));
  if (x.constrained_edges.size() != y.constrained_edges.size()) return "constrained edge counts differ";
  for (std::size_t i = 0; i < x.constrained_edges.size(); ++i) {
    const ConstrainedEdge &e = x.constrained_edges[i], &f = y.constrained_edges[i];
    if (e.a != f.a || e.b != f.b || e.segment != f.segment)
      return fmt::format("constrained edge {}: {}-{} s{} vs {}-{} s{}", i, e.a, e.b, e.segment, f.a, f.b, f.segment);
  }
  if (a.unimprovable.size() != b.unimprovable.size())
    return fmt::format("{} vs {} unimprovable", a.unimprovable.size(), b.unimprovable.size());
  for (std::size_t i = 0; i < a.unimprovable.size(); ++i) {
    const UnimprovableTriangle &u = a.unimprovable[i], &v = b.unimprovable[i];
    if (u.triangle != v.triangle || u.apex != v.apex || u.segment1 != v.segment1 || u.segment2 != v.segment2)
      return fmt::format("unimprovable {}: {} apex {} s{} s{} vs {} apex {} s{} s{}", i, tri(u.triangle), u.apex,
                         u.segment1, u.segment2, tri(v.triangle), v.apex, v.segment1, v.segment2);
  }
  for (std::size_t i = 0; i < a.unimprovable.size(); ++i) {
    const UnimprovableTriangle &u = a.unimprovable[i], &v = b.unimprovable[i];
    if (u.reason != v.reason || u.rule != v.rule || u.point != v.point)
      return fmt::format("unimprovable {} {}: {} {} ({:.17g}, {:.17g}) vs {} {} ({:.17g}, {:.17g})", i, tri(u.triangle),
                         to_string(u.reason), to_string(u.rule), u.point.x, u.point.y, to_string(v.reason), to_string(v.rule),
                         v.point.x, v.point.y);
  }
  if (a.precision_stops != b.precision_stops)
    return fmt::format("precision stops {} vs {}", a.precision_stops, b.precision_stops);
  if (a.tie_resolutions != b.tie_resolutions)
    return fmt::format("insertions through another tie resolution {} vs {}", a.tie_resolutions, b.tie_resolutions);
  return "";
}

// The first step where two traces disagree, or "".
inline std::string trace_difference(const std::vector<TraceStep>& a, const std::vector<TraceStep>& b) {
  for (std::size_t k = 0; k < a.size() && k < b.size(); ++k) {
    const TraceStep &s = a[k], &t = b[k];
    std::string what;
    if (s.bad != t.bad) what = fmt::format("bad triangle {} vs {}", tri(s.bad), tri(t.bad));
    else if (s.lepp != t.lepp) what = fmt::format("Lepp of length {} vs {}", s.lepp.size(), t.lepp.size());
    else if (s.terminal_edge != t.terminal_edge)
      what = fmt::format("terminal edge {}-{} vs {}-{}", s.terminal_edge[0], s.terminal_edge[1], t.terminal_edge[0], t.terminal_edge[1]);
    else if (s.t1 != t.t1 || s.t2 != t.t2) what = "terminal triangles";
    else if (s.rule != t.rule) what = fmt::format("rule {} vs {}", to_string(s.rule), to_string(t.rule));
    else if (s.point != t.point) what = fmt::format("point ({:.17g}, {:.17g}) vs ({:.17g}, {:.17g})", s.point.x, s.point.y, t.point.x, t.point.y);
    else if (s.split_segment != t.split_segment) what = fmt::format("split segment {} vs {}", s.split_segment, t.split_segment);
    else if (s.round != t.round) what = fmt::format("round {} vs {}", s.round, t.round);
    if (!what.empty()) return fmt::format("step {}: {}", k, what);
  }
  if (a.size() != b.size()) return fmt::format("{} vs {} steps", a.size(), b.size());
  return "";
}

}  // namespace lepp::impl_test
