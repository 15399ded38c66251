// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind lepp/certify_json.h: the certifier's report as JSON.
#include "lepp/certify_json.h"

#include <utility>

#include <fmt/format.h>

namespace lepp::certify {

nlohmann::json json_report(const Report& r, std::size_t max_listed) {
  const certify::Statistics& s = r.stats;
  nlohmann::json counts = nlohmann::json::object();
  for (std::size_t i = 0; i < r.count_by_reason.size(); ++i)
    if (r.count_by_reason[i]) counts[certify::to_string(static_cast<certify::Reason>(i))] = r.count_by_reason[i];
  nlohmann::json violations = nlohmann::json::array();
  for (const certify::Violation& v : r.violations) {
    nlohmann::json points = nlohmann::json::array();
    for (const Point& p : v.points) points.push_back({p.x, p.y});
    violations.push_back({{"reason", certify::to_string(v.reason)},
                          {"check", certify::to_string(certify::check_of(v.reason))},
                          {"message", v.message},
                          {"triangles", v.triangles},
                          {"edges", v.edges},
                          {"vertices", v.vertices},
                          {"points", points},
                          {"segment", v.segment},
                          {"region", v.region}});
  }
  nlohmann::json unimprovable = nlohmann::json::array();
  for (const UnimprovableTriangle& u : r.unimprovable_accepted)
    unimprovable.push_back({{"triangle", u.triangle},
                            {"apex", u.apex},
                            {"segment1", u.segment1},
                            {"segment2", u.segment2},
                            {"reason", to_string(u.reason)}});
  nlohmann::json precision = nlohmann::json::array();
  for (std::size_t i = 0; i < r.precision_exempt_triangles.size() && i < max_listed; ++i)
    precision.push_back(r.precision_exempt_triangles[i]);
  // The claims of double precision with their outcomes (at most max_listed; all
  // counted); a rejected one's witness, its point also in C99 hexadecimal (exact).
  nlohmann::json claims = nlohmann::json::array();
  nlohmann::json claim_counts = {{"exempt", 0}, {"rejected", 0}, {"undecided", 0}};
  for (const PrecisionClaim& c : r.precision_claims) {
    claim_counts[to_string(c.outcome)] = claim_counts[to_string(c.outcome)].get<std::size_t>() + 1;
    if (claims.size() >= max_listed) continue;
    nlohmann::json claim = {{"triangle", c.triangle}, {"outcome", to_string(c.outcome)}, {"states", c.states}};
    if (c.outcome == PrecisionOutcome::Undecided) claim["undecided"] = to_string(c.undecided);
    if (c.outcome == PrecisionOutcome::Rejected) {
      const PrecisionWitness& w = c.witness;
      claim["witness"] = {{"point", {w.point.x, w.point.y}},
                          {"point_hex", {fmt::format("{:a}", w.point.x), fmt::format("{:a}", w.point.y)}},
                          {"rounding", w.rounding},
                          {"rule", to_string(w.rule)},
                          {"lepp", w.lepp},
                          {"longest", w.longest},
                          {"terminal_other", w.terminal_other},
                          {"second1", w.second1},
                          {"second2", w.second2},
                          {"split", w.split}};
    }
    claims.push_back(std::move(claim));
  }
  nlohmann::json angles = nlohmann::json::array();
  for (const certify::SmallInputAngle& a : r.small_angles)
    angles.push_back({{"apex", a.apex},
                      {"segment1", a.segment1},
                      {"segment2", a.segment2},
                      {"angle", a.angle_deg},
                      {"radius", a.radius}});
  nlohmann::json exempt = nlohmann::json::array();
  for (std::size_t i = 0; i < r.exempt_triangles.size() && i < max_listed; ++i)
    exempt.push_back({{"triangle", r.exempt_triangles[i]}, {"small_angle", r.exempt_angle[i]}});
  nlohmann::json regions = nlohmann::json::array();
  for (std::size_t i = 0; i < r.region_places.size(); ++i)
    regions.push_back({{"region", i}, {"place", certify::to_string(r.region_places[i])}, {"triangles", r.region_triangles[i]}});
  return {{"certified", r.certified()},
          {"min_angle_checked", r.min_angle_deg},
          {"statistics",
           {{"vertices", s.vertices},
            {"triangles", s.triangles},
            {"edges", s.edges},
            {"min_angle", s.min_angle_deg},
            {"avg_min_angle", s.avg_min_angle_deg},
            {"min_area_quality", s.min_area_quality},
            {"shortest_edge", s.shortest_edge},
            {"shortest_edge_ratio", s.shortest_edge_ratio},
            {"avg_lepp_size", s.avg_lepp_size},
            {"incircle_tests", s.delaunay_edges_checked},
            {"cocircular_edges", s.cocircular_edges},
            {"constrained_edges", s.constrained_edges},
            {"terminal_pairs", s.terminal_pairs_checked},
            {"euler_mesh", s.euler_mesh},
            {"euler_domain", s.euler_domain}}},
          {"violation_counts", counts},
          {"violations", violations},
          {"unimprovable_accepted", unimprovable},
          {"small_input_angles", angles},
          {"exempt_count", r.exempt_count},
          {"exempt_triangles", exempt},
          {"precision_exempt_count", r.precision_exempt_count},
          {"precision_exempt_triangles", precision},
          {"precision_claims", claims},
          {"precision_claim_counts", claim_counts},
          {"precision_undecided", r.precision_undecided},
          {"tie_search_states", r.tie_search_states},
          {"time_limit", r.time_limit_seconds},
          {"warnings", r.warnings},
          {"size_bound",
           {{"max_area", r.max_area}, {"region_areas", r.region_area_bounds}, {"triangles_checked", r.area_checked}, {"regions", regions}}}};
}

}  // namespace lepp::certify
