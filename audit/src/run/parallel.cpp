// SPDX-License-Identifier: GPL-3.0-or-later
// -j: a few threads taking indices in turn.
#include "lepp/audit/run/parallel.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

#include "lepp/refine.h"


namespace lepp::audit {
namespace {
thread_local std::size_t t_worker = 0;
}  // namespace

std::size_t resolve_jobs(std::size_t jobs) {
  return jobs > 0 ? jobs : static_cast<std::size_t>(threads_or_cores(0));
}

std::size_t worker_index() { return t_worker; }

void parallel_for(std::size_t n, std::size_t jobs, const std::function<void(std::size_t)>& f) {
  if (jobs <= 1 || n <= 1) {
    for (std::size_t i = 0; i < n; ++i) f(i);
    return;
  }
  std::atomic<std::size_t> next{0};
  const std::size_t outer = t_worker;
  auto loop = [&](std::size_t w) {
    // Nested pools get worker numbers of their own (outer * 64 + w + 1), so scratch directories never collide.
    t_worker = outer * 64 + w + 1;
    for (std::size_t i; (i = next.fetch_add(1)) < n;) f(i);
  };
  std::vector<std::thread> threads;
  const std::size_t count = std::min(jobs, n);
  for (std::size_t w = 1; w < count; ++w) threads.emplace_back(loop, w);
  loop(0);
  t_worker = outer;
  for (std::thread& t : threads) t.join();
}

}  // namespace lepp::audit
