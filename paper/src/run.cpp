// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind lepp/paper/run.h: the record of one run of one mesher on one input at
// one angle, and the runs of a study, found by what was run.
#include "lepp/paper/run.h"

namespace lepp::paper {

Run keyed_run(const std::string& problem, const std::string& reading, const std::string& method, double theta) {
  Run r;
  r.problem = problem, r.reading = reading, r.method = method, r.theta = theta;
  return r;
}

nlohmann::json to_json(const Run& r) {
  return {{"problem", r.problem},
          {"reading", r.reading},
          {"method", r.method},
          {"order", r.order},
          {"theta", r.theta},
          {"steiner", r.steiner},
          {"finished", r.finished},
          {"outcome", r.outcome},
          {"vertices", r.stats.vertices},
          {"triangles", r.stats.triangles},
          {"min_angle", r.stats.min_angle_deg},
          {"avg_min_angle", r.stats.avg_min_angle_deg},
          {"min_area_quality", r.stats.min_area_quality},
          {"shortest_edge_ratio", r.stats.shortest_edge_ratio},
          {"avg_lepp", r.avg_lepp},
          {"seconds", r.seconds},
          {"q_hist", r.q_hist},
          {"mesh", r.mesh_prefix}};
}

const Run* Results::find(const std::string& problem, const std::string& method, double theta, const std::string& order,
                         const std::string& reading) const {
  for (const Run& r : runs_)
    if (r.problem == problem && r.method == method && r.theta == theta && r.order == order && r.reading == reading) return &r;
  return nullptr;
}

}  // namespace lepp::paper
