// SPDX-License-Identifier: GPL-3.0-or-later
// The main of a benchmark program that registers its benchmarks at run time.
#pragma once

namespace lepp::bench {

// Registers (register_all), reads Google Benchmark's flags (an unknown one:
// returns 1), runs `before_run` when given (work no clock may see), then the
// benchmarks asked for.
int bench_main(int argc, char** argv, void (*register_all)(), void (*before_run)() = nullptr);

}  // namespace lepp::bench
