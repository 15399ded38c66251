// SPDX-License-Identifier: GPL-3.0-or-later
// A pass over [0, n) on Options::threads threads: fixed ranges, each with its own list of
// violations and counters, merged in range order. The report is the one a single
// thread makes, for any count: the same violations in the same order, the same counts.
#pragma once
#include <algorithm>
#include <array>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

#include "certification.h"
#include "lepp/refine.h"

namespace lepp::certify {

// What one range of a pass found: its violations in order, and counters the pass sums.
struct RangeFindings {
  std::vector<Violation> violations;
  std::array<std::size_t, 2> counters{};
  std::size_t range = 0;  // this range's number, 0 first: for a pass's own per-range results
  void add(Violation v) { violations.push_back(std::move(v)); }
};

// How many threads a pass over [0, n) runs on: one per thread, however small n is (a
// thread costs microseconds, and small meshes, the tests', then run the same merging
// as large ones).
inline std::size_t thread_count(const Certification& cert, std::size_t n) {
  const std::size_t threads = static_cast<std::size_t>(threads_or_cores(cert.options.threads));
  return std::max<std::size_t>(1, std::min(threads, n));
}

// Ranges of about n / k items each covering [0, n): range r is [first[r], first[r + 1]).
inline std::vector<std::size_t> even_ranges(std::size_t n, std::size_t k) {
  std::vector<std::size_t> first(k + 1);
  for (std::size_t r = 0; r <= k; ++r) first[r] = n * r / k;
  return first;
}

namespace detail {

// body(first[r], first[r + 1], findings of r) for each range r, on up to `threads`
// threads, each taking the next range no thread has taken; then each range's violations
// added through cert.add in range order, and its counters summed. Which thread ran a
// range changes nothing: a range's findings are its own.
template <class Body>
std::array<std::size_t, 2> run_ranges(Certification& cert, const std::vector<std::size_t>& first, std::size_t threads, const Body& body) {
  const std::size_t ranges = first.size() - 1;
  std::vector<RangeFindings> found(ranges);
  for (std::size_t r = 0; r < ranges; ++r) found[r].range = r;
  std::vector<std::exception_ptr> failed(ranges);
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t r = next++; r < ranges; r = next++) {
      try {
        body(first[r], first[r + 1], found[r]);
      } catch (...) {
        failed[r] = std::current_exception();  // rethrown below, on the calling thread
      }
    }
  };
  threads = std::min(threads, ranges);
  if (threads <= 1) {
    work();
  } else {
    std::vector<std::thread> workers;
    for (std::size_t t = 1; t < threads; ++t) workers.emplace_back(work);
    work();
    for (std::thread& w : workers) w.join();
  }
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
  std::array<std::size_t, 2> sums{};
  for (RangeFindings& f : found) {
    for (Violation& v : f.violations) cert.add(std::move(v));
    for (std::size_t i = 0; i < sums.size(); ++i) sums[i] += f.counters[i];
  }
  return sums;
}

}  // namespace detail

// One range a thread, with the ranges' bounds given: range r is [first[r], first[r + 1])
// (first ascending, first.size() - 1 ranges). For passes that keep a large array per
// range (the half-edge index's and the adjacency's counts), or split where the work is even.
template <class Body>
std::array<std::size_t, 2> over_bounds(Certification& cert, const std::vector<std::size_t>& first, const Body& body) {
  return detail::run_ranges(cert, first, first.size() - 1, body);
}

// How many ranges over_ranges splits [0, n) into: on several threads, kRangesPerThread
// a thread, taken in turn, so that a thread whose ranges run slower (the triangles of
// the lower vertices load points from the whole array, the upper ones' from its upper
// part) leaves the others the rest, and no thread waits idle for the slowest range.
constexpr std::size_t kRangesPerThread = 8;
inline std::size_t range_count(const Certification& cert, std::size_t n) {
  const std::size_t threads = thread_count(cert, n);
  return threads == 1 ? 1 : std::min(n, threads * kRangesPerThread);
}

// Calls body(begin, end, findings) on consecutive ranges covering [0, n) (range_count of
// them: one on one thread), on thread_count threads, then adds each range's violations
// through cert.add in range order. Returns the counters summed. body may read the index
// and the options only (and write its own range's parts of arrays): the report is
// written here, after. findings.range is the range's number, for a pass's own per-range
// results (range_count of them).
template <class Body>
std::array<std::size_t, 2> over_ranges(Certification& cert, std::size_t n, const Body& body) {
  return detail::run_ranges(cert, even_ranges(n, range_count(cert, n)), thread_count(cert, n), body);
}

// Ranges of vertices [0, nv) with about as many half-edges of the index in each (the
// half-edges whose smaller end is v are v's bucket: MeshIndex::half_begin): for the
// passes over the buckets, whose lower vertices hold most edges (the smaller end of each).
inline std::vector<std::size_t> vertex_ranges_by_halves(const Certification& cert) {
  const std::vector<int>& begin = cert.index.half_begin;  // nv + 1 entries
  const std::size_t nv = begin.size() - 1, ranges = thread_count(cert, nv);
  const std::size_t halves = static_cast<std::size_t>(begin.back());
  std::vector<std::size_t> first(ranges + 1, nv);
  first[0] = 0;
  for (std::size_t r = 1; r < ranges; ++r)  // the first vertex whose bucket starts at or past r / ranges of the halves
    first[r] = static_cast<std::size_t>(std::lower_bound(begin.begin(), begin.end() - 1, static_cast<int>(halves * r / ranges)) - begin.begin());
  return first;
}

}  // namespace lepp::certify
