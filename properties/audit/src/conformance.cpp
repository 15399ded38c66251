// SPDX-License-Identifier: GPL-3.0-or-later
// The conformance check: the trace replayed on lepp::reference::Replay.
#include "lepp/audit/conformance.h"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "lepp/reference_replay.h"

namespace lepp::audit {

namespace {

ConformanceCandidate candidate(const reference::ReplayChoice& c) {
  ConformanceCandidate out;
  out.bad = c.bad;
  out.lepp = c.lepp;
  out.terminal_edge = c.terminal_edge;
  out.rule = c.rule;
  out.point = c.point;
  out.distance = c.distance;
  out.tolerance = c.tolerance;
  return out;
}

std::string tri(const Tri& t) { return fmt::format("({},{},{})", t[0], t[1], t[2]); }

}  // namespace

ConformanceReport check_conformance(const Pslg& validated, const std::vector<Point>& trace,
                                    const ConformanceOptions& options) {
  auto start = std::chrono::steady_clock::now();
  reference::ReplayRules rules;
  rules.method = options.method;
  rules.min_angle_deg = options.min_angle_deg;
  rules.angle_tolerance_deg = options.angle_tolerance_deg;
  rules.point_tolerance_ulps = options.point_tolerance_ulps;
  rules.max_area = options.max_area;
  rules.region_area_bounds = options.region_area_bounds;
  rules.follow_cocircular_flips = options.follow_cocircular_flips;
  rules.cocircular_search_budget = options.cocircular_search_budget;
  reference::Replay replay(validated, rules);

  ConformanceReport report;
  report.steps = trace.size();
  for (std::size_t i = 0; i < trace.size(); ++i) {
    const Point& p = trace[i];
    reference::ReplayChoice choice;
    std::string reason;
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
      reason = "not a finite point";
    } else if (replay.match(p, choice)) {
      try {
        replay.insert(p, choice);
        ++report.steps_checked;
        continue;
      } catch (const std::runtime_error& e) {
        reason = fmt::format("the point is a choice ({}) but cannot be inserted: {}", to_string(choice.rule), e.what());
      }
    }
    ConformanceFailure failure;
    failure.step = i;
    failure.point = p;
    failure.mesh = replay.mesh();
    std::vector<reference::ReplayChoice> all = replay.all_choices(p, 20, failure.candidates_total);
    for (const auto& c : all) failure.candidates.push_back(candidate(c));
    if (!all.empty()) failure.nearest_distance = all.front().distance;
    if (reason.empty()) {
      bool vertex = false;
      for (const Point& v : failure.mesh.vertices) vertex = vertex || v == p;
      if (vertex)
        reason = "the point is already a vertex of the mesh";
      else if (all.empty())
        reason = "the mesh has no bad triangle: no point should be inserted";
      else
        reason = fmt::format("not the paper's choice for any bad triangle's Lepp (nearest choice {:.3g} away, tolerance {:.3g})",
                             all.front().distance, all.front().tolerance);
    }
    failure.reason = reason;
    report.cocircular_search_exhausted = replay.cocircular_search_exhausted();
    report.conforms = false;
    report.failure = std::move(failure);
    break;
  }
  report.cocircular_ties = replay.cocircular_ties();
  report.cocircular_flips = replay.cocircular_flips();
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

std::string describe(const ConformanceReport& r, std::size_t max_candidates) {
  if (r.conforms) return fmt::format("conforms: {} of {} steps are the paper's choices\n", r.steps_checked, r.steps);
  const ConformanceFailure& f = *r.failure;
  std::string s = fmt::format("step {} of {}: point ({:.17g}, {:.17g}): {}\n", f.step, r.steps, f.point.x, f.point.y, f.reason);
  std::size_t n = std::min(max_candidates, f.candidates.size());
  if (n) s += fmt::format("nearest of {} choices at this step:\n", f.candidates_total);
  for (std::size_t i = 0; i < n; ++i) {
    const ConformanceCandidate& c = f.candidates[i];
    std::string lepp;
    for (const Tri& t : c.lepp) lepp += " " + tri(t);
    s += fmt::format("  ({:.17g}, {:.17g}) {} distance {:.3g}: bad {}, Lepp{}, terminal edge ({},{})\n", c.point.x, c.point.y,
                     to_string(c.rule), c.distance, tri(c.bad), lepp, c.terminal_edge[0], c.terminal_edge[1]);
  }
  if (r.cocircular_search_exhausted)
    s += "note: the search of the cocircular cells' other triangulations gave up (cocircular_search_budget): "
         "the point may be a choice of a constrained Delaunay mesh it did not reach\n";
  else if (r.cocircular_ties > 0)
    s += fmt::format("note: the mesh had {} cocircular ties and the replay flipped {} cocircular edges to follow the trace; "
                     "unless follow_cocircular_flips is off, every triangulation of the cocircular cells was searched\n",
                     r.cocircular_ties, r.cocircular_flips);
  return s;
}

}  // namespace lepp::audit
