// SPDX-License-Identifier: GPL-3.0-or-later
// Conformance check throughput: replay steps per second on the paper's
// problems (traces of the fast engine), and on cocircular lattice input
// turned by -90 degrees (the replay searches other triangulations of the
// cells), docs/CONFORMANCE.md. Not a test.
#include <benchmark/benchmark.h>

#include <string>

#include "lepp/audit/judge/conformance.h"
#include "lepp/fast.h"
#include "lepp/gen_lattice_box.h"
#include "lepp/gen_symmetry.h"
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

// Cocircular cells everywhere (lepp/gen_lattice_box.h), validated.
lepp::Pslg lattice_box(int w, int h, int every) {
  std::vector<std::string> warnings;
  return lepp::validate(lepp::gen::lattice_box(w, h, every), warnings);
}

// Args: input (0: box 40 x 30, 1: box 24 x 18 with every third row), quarter turns.
void BM_ConformanceCocircular(benchmark::State& state) {
  lepp::Pslg p = state.range(0) == 0 ? lattice_box(40, 30, 0) : lattice_box(24, 18, 3);
  const lepp::gen::LatticeSymmetry s{static_cast<int>(state.range(1)), false};
  lepp::RefineOptions o;
  o.min_angle_deg = 30;
  o.trace = true;
  lepp::RefineResult r = lepp::fast::refine(s.apply(p), o);
  std::vector<lepp::Point> trace;
  for (const lepp::TraceStep& t : r.trace) trace.push_back(s.undo(t.point));
  lepp::audit::ConformanceOptions c;
  c.min_angle_deg = 30;
  std::size_t steps = 0;
  std::int64_t flips = 0;
  for (auto _ : state) {
    lepp::audit::ConformanceReport report = lepp::audit::check_conformance(p, trace, c);
    if (!report.conforms) state.SkipWithError("trace does not conform");
    steps += report.steps_checked;
    flips = report.cocircular_flips;
  }
  state.SetLabel(std::string(state.range(0) == 0 ? "box40x30" : "box24x18/3") + " turned " +
                 std::to_string(90 * s.quarter_turns) + " (" + std::to_string(trace.size()) + " steps, " +
                 std::to_string(flips) + " flips)");
  state.SetItemsProcessed(static_cast<std::int64_t>(steps));
}

BENCHMARK(BM_ConformanceCocircular)->Args({0, 0})->Args({0, 3})->Args({1, 0})->Args({1, 3})->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
