// SPDX-License-Identifier: GPL-3.0-or-later
// `-j N` in the audit: a fixed number of threads taking indices in turn. The
// work items are runs of the program under audit (child processes the threads
// wait for), the rows on a finished run (certifier and replay: CGAL is built
// with CGAL_HAS_THREADS, objects are per thread) and comparison runs. Results
// go into slots by index, so what the audit reports does not depend on N.
#pragma once
#include <cstddef>
#include <functional>

namespace lepp::audit {

// jobs 0: the machine's cores (std::thread::hardware_concurrency, at least 1), in
// every build: isolated runs are forked by a server made before the threads
// (isolated_engine.h), so a sanitizer build may run them beside threads too.
std::size_t resolve_jobs(std::size_t jobs);

// Calls f(i) for every i in [0, n) on at most `jobs` threads (the calling thread
// alone when jobs <= 1 or n <= 1). f must not throw.
void parallel_for(std::size_t n, std::size_t jobs, const std::function<void(std::size_t)>& f);

// The number of the pool thread running the caller (0 outside parallel_for):
// lets each thread have scratch directories of its own.
std::size_t worker_index();

}  // namespace lepp::audit
