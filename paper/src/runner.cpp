// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind lepp/paper/runner.h: one run of one mesher on one input at one angle.
#include "lepp/paper/runner.h"

#include <algorithm>
#include <chrono>
#include <exception>

#include <fmt/format.h>

#include "cgal_mesher.h"
#include "lepp/engines/registry.h"
#include "lepp/io.h"
#include "lepp/stats.h"
#include "triangle_wasm.h"
#include "mesher_names.h"

namespace lepp::paper {
namespace {

std::string theta_tag(double theta) { return fmt::format("{:g}", theta); }

}  // namespace

std::vector<int> quality_histogram(const Mesh& mesh) {
  std::vector<int> hist(20, 0);
  for (const Tri& t : mesh.triangles) {
    double q = area_quality(mesh.vertices[static_cast<std::size_t>(t[0])], mesh.vertices[static_cast<std::size_t>(t[1])],
                            mesh.vertices[static_cast<std::size_t>(t[2])]);
    hist[static_cast<std::size_t>(std::clamp(q, 0.0, 0.999999) * 20)]++;
  }
  return hist;
}

RefineResult Runner::refine(const Pslg& pslg, const RefineOptions& options) {
  // auto: the fast engine.
  const engines::Engine which = engines::parse_engine(options_.engine, engines::lepp_engines()).value_or(engines::Engine::Fast);
  engine_ = engines::to_string(which);
  return engines::refine(which, pslg, options);
}

Run Runner::lepp_run(const std::string& problem, const std::string& reading, const Pslg& pslg, const std::string& method,
                     double theta, const std::string& order) {
  Run r = start(problem, reading, method, theta);
  r.order = order;
  RefineOptions o;
  o.min_angle_deg = theta;
  o.method = engines::parse_method(method).value();
  o.order = engines::parse_order(order).value();
  if (o.order != QueueOrder::Fifo) r.mesh_prefix += "-" + order;
  o.max_steiner = options_.budget;
  o.time_limit_seconds = options_.time_limit;
  try {
    auto t0 = std::chrono::steady_clock::now();
    RefineResult res = refine(pslg, o);
    double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.steiner = res.steiner_points;
    r.finished = res.outcome == Outcome::Converged || res.outcome == Outcome::Unimprovable;
    r.outcome = to_string(res.outcome);
    r.avg_lepp = average_lepp_size(res);
    r.seconds = wall;
    finish(r, res.mesh, pslg);
  } catch (const std::exception& e) {
    r.outcome = std::string("engine error: ") + e.what();
  }
  return r;
}

Run Runner::cgal_run(const std::string& problem, const std::string& reading, const Pslg& pslg, double theta) {
  Run r = start(problem, reading, cgal_name(), theta);
  others::CgalMeshLimits limits;
  limits.max_steiner = options_.budget;
  limits.time_limit_seconds = std::min(options_.time_limit, 20.0);
  others::CgalMeshResult res = others::cgal_mesh(pslg, theta, 0, limits);
  r.steiner = res.steiner_points;
  r.finished = res.finished;
  r.outcome = res.finished ? "converged" : "did-not-finish";
  r.seconds = res.seconds;
  finish(r, res.mesh, pslg);
  return r;
}

Run Runner::triangle_run(const std::string& problem, const std::string& reading, const std::string& poly, const Pslg& pslg,
                         double theta) {
  Run r = start(problem, reading, triangle_name(), theta);
  // -S: Triangle's own Steiner budget, so that a run above its range ends too.
  others::TriangleRun tr = others::run_triangle(options_.root, poly, theta, options_.triangle_budget, r.mesh_prefix);
  r.seconds = tr.seconds;
  const std::string& output = tr.output;
  int status = tr.status;
  long long added = tr.points_added;
  if (status == 0 && added >= 0) {
    r.steiner = added;
    try {
      Mesh m = read_mesh(r.mesh_prefix);
      finish(r, m, pslg);
      // Triangle stopped by -S still exits 0: it finished only if no angle is left below theta.
      r.finished = added < options_.triangle_budget && r.stats.min_angle_deg >= theta - kAngleSlack;
      r.outcome = r.finished ? "converged" : "did-not-finish";
    } catch (const std::exception& e) {
      r.outcome = std::string("unreadable output: ") + e.what();
    }
  } else {
    std::string first = output.substr(0, output.find('\n'));
    r.outcome = status == 77 ? "triangle-wasm not installed" : fmt::format("triangle failed ({}): {}", status, first);
  }
  return r;
}

bool Runner::triangle_available() const { return others::triangle_available(options_.root); }

Run Runner::start(const std::string& problem, const std::string& reading, const std::string& method, double theta) const {
  Run r = keyed_run(problem, reading, method, theta);
  r.mesh_prefix = fmt::format("{}/meshes/{}-{}-{}", options_.work, reading.empty() ? problem : reading, method, theta_tag(theta));
  return r;
}

// Our meshes and CGAL's are written for the drawings; Triangle wrote its own.
void Runner::finish(Run& r, const Mesh& mesh, const Pslg& pslg) const {
  r.stats = mesh_stats(mesh, pslg);
  r.q_hist = quality_histogram(mesh);
  if (r.method != triangle_name()) write_mesh(r.mesh_prefix, mesh);
}

}  // namespace lepp::paper
