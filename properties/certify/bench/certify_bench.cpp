// SPDX-License-Identifier: GPL-3.0-or-later
// The certifier's speed on large meshes: Circles240 refined by the fast engine at
// 30 degrees with a size bound chosen for about N triangles, then certified in full
// (topology, coverage, chains, Delaunay, min angle, Theorem 2, statistics).
//   build-x/properties/certify/bench/certify_bench --benchmark_min_time=1
#include <benchmark/benchmark.h>

#include <map>

#include "lepp/certify.h"
#include "lepp/fast.h"
#include "lepp/io.h"
#include "lepp/validate.h"

namespace {

struct Case {
  lepp::Pslg pslg;
  lepp::Mesh mesh;
};

const Case& refined(std::int64_t triangles) {
  static std::map<std::int64_t, Case> cache;
  auto it = cache.find(triangles);
  if (it != cache.end()) return it->second;
  std::vector<std::string> warnings;
  Case c;
  c.pslg = lepp::validate(lepp::read_poly(LEPP_SOURCE_DIR "/corpus/paper/circles240.poly"), warnings);
  lepp::RefineOptions o;
  o.min_angle_deg = 30;
  o.max_area = 3.0 / static_cast<double>(triangles);  // the domain's area is about 3
  o.max_steiner = 4 * triangles;
  c.mesh = lepp::fast::refine(c.pslg, o).mesh;
  return cache.emplace(triangles, std::move(c)).first->second;
}

void BM_CertifyRefinedCircles(benchmark::State& state) {
  const Case& c = refined(state.range(0));
  lepp::certify::Options o;
  o.min_angle_deg = 30;
  bool ok = true;
  for (auto _ : state) {
    const lepp::certify::Report r = lepp::certify::certify(c.pslg, c.mesh, o);
    ok = ok && r.certified();
    benchmark::DoNotOptimize(r.stats.avg_lepp_size);
  }
  if (!ok) state.SkipWithError("mesh not certified");
  state.counters["triangles"] = static_cast<double>(c.mesh.triangles.size());
  state.counters["triangles/s"] =
      benchmark::Counter(static_cast<double>(c.mesh.triangles.size()), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_CertifyRefinedCircles)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
