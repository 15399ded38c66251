// SPDX-License-Identifier: GPL-3.0-or-later
// Fresh pages for the fast engine's growing arrays a chunk at a time (issue 40).
//
// The points, triangles and stamps grow into capacity reserved at the start, and
// each 4 KiB page of it is a page fault when first written: about 2 us each on the
// virtual machines measured, a tenth of a 10^6-triangle refinement
// (docs/BENCHMARKS.md). Linux populates a range of pages in one call
// (madvise MADV_POPULATE_WRITE) for less, and with a second thread that thread does
// it, ahead of the refinement. Only pages within an array's reserved capacity are
// populated, never its contents touched: the mesh is the same, and elsewhere than
// on Linux (or on a kernel without the call) nothing is done.
#pragma once
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

#include "pages.h"
#include "tri_mesh.h"

namespace lepp::fast {

class PopulateAhead {
 public:
  // advance() is called after every kEvery insertions: between two calls the
  // arrays grow by at most kEvery points and 2 kEvery triangle slots (an insertion
  // adds one vertex and at most two slots), the bound the thread's safety rests on.
  static constexpr std::int64_t kEvery = 1024;
  // Each array is populated to this many bytes past its end, once it has this many.
  static constexpr std::size_t kLead = std::size_t{1} << 20;

  // beside: populate on a thread of its own (started at the first chunk to populate).
  explicit PopulateAhead(bool beside) : beside_(beside) {}
  ~PopulateAhead();
  PopulateAhead(const PopulateAhead&) = delete;
  PopulateAhead& operator=(const PopulateAhead&) = delete;

  void advance(const TriMesh& m);
  // Waits for the population under way and starts no more: before the arrays are freed.
  void finish();
  // Waits until every population asked so far is done (tests).
  void wait();

 private:
  // One array's buffer and how far into its capacity it is populated.
  struct Array {
    std::uintptr_t data = 0;
    std::size_t populated = 0;  // bytes from data
    bool stopped = false;       // near the end of its capacity: left alone until it moves
  };
  // bytes, capacity: the array's in use and reserved; growth: the most it can grow between calls.
  void advance(Array& a, const void* data, std::size_t bytes, std::size_t capacity, std::size_t growth);
  void run();

  const bool beside_;
  Array pts_, tris_, stamp_;
  std::atomic<bool> unsupported_{false};  // the call failed once: no more
  std::thread thread_;
  std::mutex mutex_;
  std::condition_variable work_, idle_;
  std::vector<Pages> pending_;
  bool busy_ = false;
  // finish() was called: written under the lock, read without it only by the thread
  // that calls advance() and finish().
  bool closing_ = false;
};

}  // namespace lepp::fast
