// SPDX-License-Identifier: GPL-3.0-or-later
// impl vs reference vs CGAL's mesher, in the same run (docs/BENCHMARKS.md).
//   lepp_bench [--benchmark_filter=...]         paper corpus at 30 degrees, generated 1e4..1e6 triangles
//   LEPP_BENCH_HUGE=1 lepp_bench                 adds the 1e7-triangle problem (fast engine only)
// Counters: steiner and triangles made, Steiner points per CPU second, peak
// resident bytes per output triangle (VmHWM above the resident size at the start).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>
#include <string>

#include "bench_main.h"
#include "cgal_mesher.h"
#include "lepp/engines/registry.h"
#include "lepp/fast.h"
#include "lepp/reference.h"
#include "memory_probe.h"
#include "problems.h"

namespace lepp::bench {
namespace {

struct Outcome {
  std::int64_t steiner = 0;
  std::size_t triangles = 0, vertices = 0;
  bool finished = true;
};
using Engine = std::function<Outcome(const Problem&)>;

Outcome outcome_of(const RefineResult& r) {
  return {r.steiner_points, r.mesh.triangles.size(), r.mesh.vertices.size(), r.outcome == lepp::Outcome::Converged};
}

Outcome run_fast(const Problem& p) { return outcome_of(fast::refine(p.pslg, refine_options(p))); }
Outcome run_reference(const Problem& p) { return outcome_of(reference::refine(p.pslg, refine_options(p))); }

// CGAL's mesher with B = sin^2(theta) and, for a size-bounded problem, the
// longest-edge bound that gives about the fast engine's vertex count:
// h = c / sqrt(V), c fitted once on the smallest generated problem.
double cgal_edge_constant = 0;
std::map<std::string, std::size_t> fast_vertices;

std::size_t fast_vertex_count(const Problem& p) {
  auto it = fast_vertices.find(p.name);
  if (it != fast_vertices.end()) return it->second;
  return fast_vertices[p.name] = run_fast(p).vertices;
}

double cgal_edge_bound(const Problem& p) {
  if (p.max_area <= 0) return 0;
  if (cgal_edge_constant == 0) {
    Problem small = square_with_size_bound(1e4);
    double target = static_cast<double>(fast_vertex_count(small));
    double c = std::sqrt(2 / std::sqrt(3.0));
    for (int k = 0; k < 3; ++k) {
      auto r = others::cgal_mesh(small.pslg, small.theta, c / std::sqrt(target));
      c *= std::sqrt(static_cast<double>(r.mesh.vertices.size()) / target);
    }
    cgal_edge_constant = c;
  }
  return cgal_edge_constant / std::sqrt(static_cast<double>(fast_vertex_count(p)));
}

Outcome run_cgal(const Problem& p) {
  others::CgalMeshLimits limits;
  limits.max_steiner = 50 * static_cast<std::int64_t>(fast_vertex_count(p)) + 100000;
  limits.time_limit_seconds = 300;
  auto r = others::cgal_mesh(p.pslg, p.theta, cgal_edge_bound(p), limits);
  return {r.steiner_points, r.mesh.triangles.size(), r.mesh.vertices.size(), r.finished};
}

const Engine fast_engine = run_fast, reference_engine = run_reference, cgal_engine = run_cgal;

void bench(benchmark::State& state, const Problem* problem, const Engine* engine) {
  // CGAL's size bound is fitted before the clock starts.
  if (engine == &cgal_engine) cgal_edge_bound(*problem);
  Outcome out;
  double peak_per_triangle = 0;
  bool first = true;
  for (auto _ : state) {
    long start = first ? start_peak_measure() : 0;
    out = (*engine)(*problem);
    if (first) {
      peak_per_triangle = static_cast<double>(peak_since(start)) / static_cast<double>(std::max<std::size_t>(out.triangles, 1));
      first = false;
    }
  }
  state.counters["steiner"] = static_cast<double>(out.steiner);
  state.counters["triangles"] = static_cast<double>(out.triangles);
  state.counters["steiner_per_cpu_s"] = benchmark::Counter(static_cast<double>(out.steiner), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["peak_bytes_per_tri"] = peak_per_triangle;
  state.counters["finished"] = out.finished ? 1 : 0;
}

// Problems and engines live for the whole run: benchmarks hold pointers to them.
std::vector<Problem>& problems() {
  static std::vector<Problem> all;
  return all;
}

void register_all() {
  auto& all = problems();
  all = paper_problems(std::string(LEPP_SOURCE_DIR) + "/corpus/paper", 30);
  const std::size_t paper = all.size();
  for (double t : {1e4, 1e5, 1e6}) all.push_back(square_with_size_bound(t));
  all.push_back(random_points(100000));
  const bool huge = std::getenv("LEPP_BENCH_HUGE") != nullptr;
  if (huge) all.push_back(square_with_size_bound(1e7));
  for (std::size_t i = 0; i < all.size(); ++i) {
    const Problem* p = &all[i];
    const bool big = i >= paper && p->max_area > 0 && p->max_area < 1.4 / 2e5;
    const bool very_big = i >= paper && p->max_area > 0 && p->max_area < 1.4 / 2e6;
    auto add = [&](const char* engine_name, const Engine* e) {
      auto* b = benchmark::RegisterBenchmark((p->name + "/" + engine_name).c_str(), bench, p, e);
      b->Unit(benchmark::kMillisecond);
      if (i >= paper) b->Iterations(1);
    };
    add(engines::to_string(engines::Engine::Fast), &fast_engine);
    if (!big && p->name.rfind("random", 0) != 0) add(engines::to_string(engines::Engine::Reference), &reference_engine);
    if (!very_big) add(engines::to_string(engines::Engine::Cgal), &cgal_engine);
  }
}

}  // namespace
}  // namespace lepp::bench

int main(int argc, char** argv) { return lepp::bench::bench_main(argc, argv, lepp::bench::register_all); }
