// SPDX-License-Identifier: GPL-3.0-or-later
// What `lepp refine` prints of a run: its statistics as JSON (--json) or as text.
#include "lepp/engines/refine_summary.h"

#include <chrono>
#include <cstddef>
#include <iterator>
#include <string>

#include <fmt/format.h>

#include "lepp/stats.h"
#include "lepp/version.h"

namespace lepp::engines {
namespace {

// The triangles left at double precision; the rest were left by small input angles.
std::size_t left_at_precision(const RefineResult& result) {
  std::size_t at_precision = 0;
  for (const UnimprovableTriangle& u : result.unimprovable) at_precision += u.reason == LeftReason::DoublePrecision;
  return at_precision;
}

}  // namespace

nlohmann::json refine_json_summary(const RefineRequest& request, const RefineInput& in, const RefineResult& result) {
  const auto start = std::chrono::steady_clock::now();
  RefineWritten unwritten;
  unwritten.stats = mesh_stats(result.mesh, in.pslg);
  unwritten.statistics_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  unwritten.write_seconds = -1;
  return refine_json_summary(request, in, result, unwritten);
}

nlohmann::json refine_json_summary(const RefineRequest& request, const RefineInput& in, const RefineResult& result,
                                   const RefineWritten& written) {
  const RefineOptions options = refine_options(request);
  const Pslg& input = in.pslg;
  const MeshStats& s = written.stats;
  const std::size_t at_precision = left_at_precision(result);
  nlohmann::json j = {
      {"input", request.input},
      {"output", request.output},
      {"engine", request.engine},
      {"method", to_string(options.method)},
      {"order", to_string(options.order)},
      // Fields that mean something under one order only are null under the others.
      {"order_seed", options.order == QueueOrder::Random ? nlohmann::json(options.order_seed) : nlohmann::json()},
      {"rounds", options.order == QueueOrder::Batch ? nlohmann::json(result.rounds) : nlohmann::json()},
      {"looks", options.order == QueueOrder::Batch ? nlohmann::json(result.looks) : nlohmann::json()},
      {"min_angle_target", request.min_angle},
      {"max_area", request.max_area},
      {"region_areas", request.region_areas},
      {"input_vertices", input.vertices.size()},
      {"steiner_points", result.steiner_points},
      {"vertices", s.vertices},
      {"triangles", s.triangles},
      {"min_angle", s.min_angle_deg},
      {"avg_min_angle", s.avg_min_angle_deg},
      {"min_area_quality", s.min_area_quality},
      {"shortest_edge_ratio", s.shortest_edge_ratio},
      {"avg_lepp_size", average_lepp_size(result)},
      {"cocircular_ties", result.cocircular_ties},
      {"area_refined", result.area_refined},
      {"unimprovable", result.unimprovable.size()},
      {"unimprovable_by_reason",
       {{to_string(LeftReason::SmallInputAngle), result.unimprovable.size() - at_precision},
        {to_string(LeftReason::DoublePrecision), at_precision}}},
      {"precision_stops", result.precision_stops},
      {"tie_resolutions", result.tie_resolutions},
      {"tie_search_states", options.tie_search_states},
      {"outcome", to_string(result.outcome)},
      {"stuck", result.stuck},
      {"seconds", result.seconds},
      // Where the process's time goes (wall seconds; docs/BENCHMARKS.md): cdt and
      // refine make up "seconds".
      {"seconds_by_phase",
       {{"read", in.seconds},
        {"cdt", result.cdt_seconds},
        {"refine", result.seconds - result.cdt_seconds},
        {"write", written.write_seconds >= 0 ? nlohmann::json(written.write_seconds) : nlohmann::json()},
        {"statistics", written.statistics_seconds}}},
      {"warnings", in.warnings},
  };
  // The triangles left at double precision (1-based ids as in PREFIX.unimprovable), the first 50.
  nlohmann::json limited = nlohmann::json::array();
  for (const UnimprovableTriangle& u : result.unimprovable)
    if (u.reason == LeftReason::DoublePrecision && limited.size() < 50)
      limited.push_back({{"triangle", {u.triangle[0] + 1, u.triangle[1] + 1, u.triangle[2] + 1}},
                         {"reason", to_string(u.reason)},
                         {"rule", to_string(u.rule)},
                         {"point", {u.point.x, u.point.y}}});
  j["unimprovable_at_precision"] = limited;
  add_version(j);
  return j;
}

std::string refine_text_summary(const RefineRequest& request, const RefineInput& in, const RefineResult& result,
                                const RefineWritten& written) {
  const RefineOptions options = refine_options(request);
  const MeshStats& s = written.stats;
  const std::size_t at_precision = left_at_precision(result);
  std::string text;
  auto out = std::back_inserter(text);
  fmt::format_to(out, "input vertices        {}\n", in.pslg.vertices.size());
  fmt::format_to(out, "Steiner points added  {}\n", static_cast<long long>(result.steiner_points));
  fmt::format_to(out, "triangles             {}\n", s.triangles);
  fmt::format_to(out, "smallest angle        {:.4f} deg\n", s.min_angle_deg);
  fmt::format_to(out, "average smallest      {:.4f} deg\n", s.avg_min_angle_deg);
  fmt::format_to(out, "smallest area quality {:.4f}\n", s.min_area_quality);
  fmt::format_to(out, "shortest edge / input {:.4f}\n", s.shortest_edge_ratio);
  fmt::format_to(out, "average Lepp size     {:.3f}\n", average_lepp_size(result));
  // The size bound's line only when one applied; the unimprovable's only when some were left.
  if (request.max_area > 0 || request.region_areas)
    fmt::format_to(out, "refined for area      {} triangles (too big for their bound)\n",
                   static_cast<long long>(result.area_refined));
  if (!result.unimprovable.empty())
    fmt::format_to(out,
                   "unimprovable          {} triangles ({} by small input angles, {} at double precision; listed in "
                   "{}.unimprovable)\n",
                   result.unimprovable.size(), result.unimprovable.size() - at_precision, at_precision, request.output);
  // The bound those were left at: their certificate is asked at the same --tie-search-states (CERTIFIER.md 5c).
  if (at_precision > 0)
    fmt::format_to(out, "tie search bound      {}\n",
                   options.tie_search_states == 0 ? std::string("none") : fmt::format("{} Lepp states", options.tie_search_states));
  if (options.order == QueueOrder::Random)
    fmt::format_to(out, "processing order      random (seed {})\n", static_cast<unsigned long long>(options.order_seed));
  else if (options.order == QueueOrder::Batch)
    fmt::format_to(out, "processing order      batch ({} rounds)\n", static_cast<long long>(result.rounds));
  else
    fmt::format_to(out, "processing order      {}\n", to_string(options.order));
  fmt::format_to(out, "outcome               {}\n", to_string(result.outcome));
  if (!result.stuck.empty()) fmt::format_to(out, "stuck at              {}\n", result.stuck);
  fmt::format_to(out, "seconds               {:.3f}\n", result.seconds);
  return text;
}

}  // namespace lepp::engines
