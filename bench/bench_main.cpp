// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind bench_main.h: the main of a benchmark program that registers its
// benchmarks at run time.
#include "bench_main.h"

#include <benchmark/benchmark.h>

namespace lepp::bench {

int bench_main(int argc, char** argv, void (*register_all)(), void (*before_run)()) {
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  if (before_run) before_run();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace lepp::bench
