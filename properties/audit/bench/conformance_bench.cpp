// SPDX-License-Identifier: GPL-3.0-or-later
// Conformance check throughput: replay steps per second on the paper's
// problems (traces of the fast engine), docs/CONFORMANCE.md. Not a test.
#include <benchmark/benchmark.h>

#include <string>

#include "lepp/audit/conformance.h"
#include "lepp/fast.h"
#include "lepp/io.h"
#include "lepp/validate.h"

namespace {

const char* const kProblems[] = {"A", "rect162", "square400", "circles240"};

void BM_Conformance(benchmark::State& state) {
  std::string name = kProblems[state.range(0)];
  double theta = static_cast<double>(state.range(1));
  lepp::Method method = state.range(2) ? lepp::Method::Midpoint : lepp::Method::Centroid;
  std::vector<std::string> warnings;
  lepp::Pslg p = lepp::validate(lepp::read_poly(std::string(LEPP_SOURCE_DIR) + "/corpus/paper/" + name + ".poly"), warnings);
  lepp::RefineOptions o;
  o.min_angle_deg = theta;
  o.method = method;
  o.trace = true;
  lepp::RefineResult r = lepp::fast::refine(p, o);
  std::vector<lepp::Point> trace;
  for (const lepp::TraceStep& s : r.trace) trace.push_back(s.point);
  lepp::audit::ConformanceOptions c;
  c.min_angle_deg = theta;
  c.method = method;
  std::size_t steps = 0;
  for (auto _ : state) {
    lepp::audit::ConformanceReport report = lepp::audit::check_conformance(p, trace, c);
    if (!report.conforms) state.SkipWithError("trace does not conform");
    steps += report.steps_checked;
  }
  state.SetLabel(name + " " + lepp::to_string(method) + " " + std::to_string(static_cast<int>(theta)) + " (" +
                 std::to_string(trace.size()) + " steps)");
  state.SetItemsProcessed(static_cast<std::int64_t>(steps));
}

void Args(benchmark::internal::Benchmark* b) {
  for (int problem = 0; problem < 4; ++problem) {
    for (int theta : {20, 25, 30}) b->Args({problem, theta, 0});
    b->Args({problem, 20, 1});
  }
}

BENCHMARK(BM_Conformance)->Apply(Args)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
