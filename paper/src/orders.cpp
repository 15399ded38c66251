// SPDX-License-Identifier: GPL-3.0-or-later
// The runs of the processing-order study and their JSON.
#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>

#include "lepp/engines/registry.h"
#include "lepp/io.h"
#include "lepp/paper/numbers.h"
#include "lepp/paper/orders.h"
#include "lepp/stats.h"
#include "lepp/validate.h"

namespace fs = std::filesystem;

namespace lepp::paper {

std::int64_t order_budget(const std::string& problem, double theta, double budget_factor) {
  const std::vector<int>& angles = table_angles();
  for (const auto& p : paper_problems()) {
    if (p.key != problem) continue;
    int count = p.centroid.back();
    for (std::size_t i = 0; i < angles.size(); ++i)
      if (angles[i] >= theta && p.centroid[i] > 0) {
        count = p.centroid[i];
        break;
      }
    return static_cast<std::int64_t>(budget_factor * count);
  }
  return static_cast<std::int64_t>(budget_factor * 1000);  // not a paper problem
}

OrderStudy run_order_study(const OrderStudyOptions& options, const std::function<void(const OrderRun&)>& progress) {
  OrderStudy study;
  study.options = options;
  if (study.options.problems.empty())
    for (const auto& p : paper_problems()) study.options.problems.push_back(p.key);
  if (study.options.angles.empty())
    for (int t = 28; t <= 38; ++t) study.options.angles.push_back(t);
  const OrderStudyOptions& o = study.options;
  const auto wall0 = std::chrono::steady_clock::now();
  const std::clock_t cpu0 = std::clock();

  // The named orders, then random seeds 1..N.
  std::vector<std::pair<QueueOrder, std::uint64_t>> orders;
  for (QueueOrder q : all_queue_orders())
    if (q != QueueOrder::Random) orders.push_back({q, 0});
  for (int s = 1; s <= o.random_orders; ++s) orders.push_back({QueueOrder::Random, static_cast<std::uint64_t>(s)});

  // Any name but reference (the options say fast) is the fast engine.
  const engines::Engine engine = engines::parse_engine(o.engine, engines::lepp_engines()).value_or(engines::Engine::Fast);
  for (const std::string& problem : o.problems) {
    std::vector<std::string> warnings;
    const Pslg pslg = validate(read_poly((fs::path(o.root) / "corpus" / "paper" / (problem + ".poly")).string()), warnings);
    for (const std::string& method : o.methods)
      for (double theta : o.angles)
        for (const auto& [order, seed] : orders) {
          RefineOptions ro;
          ro.min_angle_deg = theta;
          ro.method = engines::parse_method(method).value();
          ro.order = order;
          ro.order_seed = seed;
          ro.max_steiner = order_budget(problem, theta, o.budget_factor);
          ro.time_limit_seconds = o.time_limit;
          const auto t0 = std::chrono::steady_clock::now();
          RefineResult res = engines::refine(engine, pslg, ro);
          OrderRun r;
          r.problem = problem, r.method = method, r.order = to_string(order), r.theta = theta, r.seed = seed;
          r.steiner = res.steiner_points, r.budget = ro.max_steiner;
          r.outcome = to_string(res.outcome);
          r.converged = res.outcome == Outcome::Converged;
          MeshStats s = mesh_stats(res.mesh, pslg);
          r.min_angle = s.min_angle_deg, r.avg_min_angle = s.avg_min_angle_deg;
          r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          if (progress) progress(r);
          study.runs.push_back(std::move(r));
        }
  }
  study.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  study.cpu_seconds = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
  return study;
}

nlohmann::json to_json(const OrderStudy& study) {
  const OrderStudyOptions& o = study.options;
  nlohmann::json j = {{"engine", o.engine},         {"problems", o.problems},   {"methods", o.methods},
                      {"angles", o.angles},         {"random_orders", o.random_orders},
                      {"budget_factor", o.budget_factor}, {"time_limit", o.time_limit},
                      {"seconds", study.seconds},   {"cpu_seconds", study.cpu_seconds},
                      {"command", study.command}};
  j["runs"] = nlohmann::json::array();
  for (const OrderRun& r : study.runs)
    j["runs"].push_back({{"problem", r.problem}, {"method", r.method}, {"order", r.order}, {"theta", r.theta},
                         {"seed", r.seed}, {"steiner", r.steiner}, {"budget", r.budget}, {"outcome", r.outcome},
                         {"converged", r.converged}, {"min_angle", r.min_angle}, {"avg_min_angle", r.avg_min_angle},
                         {"seconds", r.seconds}});
  return j;
}

OrderStudy order_study_from_json(const nlohmann::json& j) {
  OrderStudy s;
  OrderStudyOptions& o = s.options;
  o.engine = j.at("engine");
  o.problems = j.at("problems").get<std::vector<std::string>>();
  o.methods = j.at("methods").get<std::vector<std::string>>();
  o.angles = j.at("angles").get<std::vector<double>>();
  o.random_orders = j.at("random_orders");
  o.budget_factor = j.at("budget_factor");
  o.time_limit = j.at("time_limit");
  s.seconds = j.at("seconds");
  s.cpu_seconds = j.at("cpu_seconds");
  s.command = j.value("command", std::string());
  for (const auto& x : j.at("runs")) {
    OrderRun r;
    r.problem = x.at("problem"), r.method = x.at("method"), r.order = x.at("order");
    r.theta = x.at("theta"), r.seed = x.at("seed"), r.steiner = x.at("steiner"), r.budget = x.at("budget");
    r.outcome = x.at("outcome"), r.converged = x.at("converged");
    r.min_angle = x.at("min_angle"), r.avg_min_angle = x.at("avg_min_angle"), r.seconds = x.at("seconds");
    s.runs.push_back(r);
  }
  return s;
}

}  // namespace lepp::paper
