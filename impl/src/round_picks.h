// SPDX-License-Identifier: GPL-3.0-or-later
// The batch order's selection on several threads (ALGORITHM.md section 7, "batch",
// "Threads"). A round is taken in windows of its queue. For each triangle of a
// window not yet touched, the threads compute its Lepp, its choice and, for a plain
// choice, its region (Lepp, cavity, ring) on the mesh as the window begins; then one
// thread takes the members in queue order and inserts them, exactly as the
// one-thread loop does. Every triangle that no member of the round touched is the
// same on that mesh as on the mesh of the moment (the marks cover every triangle an
// insertion destroyed, made, relinked or changed in place), so a triangle whose
// region is untouched has the same Lepp, choice and region in both, and one whose
// region is touched waits in both. The mesh is the same for every number of threads;
// the work of a triangle that an earlier member of its window touches is lost.
#pragma once
#include <algorithm>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

#include "bad_queue.h"
#include "batch_rounds.h"
#include "lepp_search.h"
#include "point_selection.h"

namespace lepp::fast {

// One triangle of a window as the mesh was when the window began.
struct Pick {
  bool waits = false;  // its Lepp or region already touched: it waits for the next round
  bool plain = false;  // plain_choice: a member anywhere in the round; else only first
  Lepp lepp;
  Choice choice;
  std::vector<int> region;  // plain: the Lepp's path, then the cavity and its ring
};

// The threads a window of n triangles is worth, with windows of `per_thread`
// entries per thread: fewer for small ones (a thread's start costs about as much as
// a few dozen Lepp searches), none below a quarter window per thread.
inline int threads_for(std::size_t n, int threads, std::size_t per_thread) {
  const std::size_t least = std::max<std::size_t>(1, per_thread / 4);
  return static_cast<int>(std::max<std::size_t>(1, std::min<std::size_t>(static_cast<std::size_t>(threads), n / least)));
}

// Fills picks[k] for round[which[k]], split in contiguous parts, one per thread.
// Reads the mesh and the marks only: with several threads, the longest-edge cache
// is not filled (edge_order.h), so nothing is written. The obstacles are not read: plain_choice
// decides a split rounded outside the domain before the sliver clause would.
inline void pick_window(TriMesh& m, const std::vector<Item>& round, const std::vector<std::size_t>& which,
                        const RoundMarks& marks, Method method, SliverObstacles& obstacles, int threads,
                        std::size_t per_thread, std::vector<Pick>& picks) {
  if (picks.size() < which.size()) picks.resize(which.size());
  auto pick_part = [&](std::size_t begin, std::size_t end, std::vector<int>& cavity) {
    for (std::size_t k = begin; k < end; ++k) {
      Pick& p = picks[k];
      lepp_search(m, round[which[k]].tri, p.lepp);
      p.waits = false;
      for (int ti : p.lepp.path) p.waits = p.waits || marks.touched(ti);
      p.region.clear();
      if (p.waits) continue;
      p.choice = select_point(m, p.lepp, method);
      p.plain = plain_choice(m, p.lepp, p.choice, obstacles);
      if (!p.plain) continue;
      p.region.assign(p.lepp.path.begin(), p.lepp.path.end());
      p.waits = !cavity_and_ring(m, p.choice, marks, p.region, cavity);
    }
  };
  const std::size_t n = which.size();
  const int t = threads_for(n, threads, per_thread);
  std::vector<std::vector<int>> cavities(static_cast<std::size_t>(t));
  if (t == 1) {
    pick_part(0, n, cavities[0]);
    return;
  }
  std::vector<std::exception_ptr> failed(static_cast<std::size_t>(t));
  auto part = [&](int k) {
    const auto uk = static_cast<std::size_t>(k), ut = static_cast<std::size_t>(t);
    try {
      pick_part(n * uk / ut, n * (uk + 1) / ut, cavities[uk]);
    } catch (...) {
      failed[uk] = std::current_exception();
    }
  };
  std::vector<std::thread> workers;
  workers.reserve(static_cast<std::size_t>(t - 1));
  m.cache_longest = false;
  for (int k = 1; k < t; ++k) workers.emplace_back(part, k);
  part(0);
  for (std::thread& w : workers) w.join();
  m.cache_longest = true;
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

}  // namespace lepp::fast
