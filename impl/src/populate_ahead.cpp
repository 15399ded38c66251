// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind populate_ahead.h.
#include "populate_ahead.h"

#include <algorithm>
#include <system_error>

#include "pages.h"

namespace lepp::fast {

PopulateAhead::~PopulateAhead() { finish(); }

void PopulateAhead::finish() {
  std::unique_lock<std::mutex> lock(mutex_);
  closing_ = true;
  pending_.clear();  // what is under way finishes; nothing more starts
  lock.unlock();
  if (!thread_.joinable()) return;
  work_.notify_one();
  thread_.join();
}

void PopulateAhead::advance(const TriMesh& m) {
  if (closing_ || unsupported_) return;
  const std::size_t points = static_cast<std::size_t>(kEvery), slots = 2 * points;
  advance(pts_, m.pts.data(), m.pts.size() * sizeof(Point), m.pts.capacity() * sizeof(Point), points * sizeof(Point));
  advance(tris_, m.tris.data(), m.tris.size() * sizeof(FTri), m.tris.capacity() * sizeof(FTri), slots * sizeof(FTri));
  advance(stamp_, m.stamp.data(), m.stamp.size() * sizeof(std::uint32_t), m.stamp.capacity() * sizeof(std::uint32_t),
          slots * sizeof(std::uint32_t));
}

void PopulateAhead::advance(Array& a, const void* data, std::size_t bytes, std::size_t capacity, std::size_t growth) {
  const auto at = reinterpret_cast<std::uintptr_t>(data);
  if (at != a.data) a = Array{at, bytes, false};  // a new buffer (or the first call): populated as far as it is used
  if (a.stopped || bytes < kLead) return;         // a small mesh takes its few faults
  // The buffer is freed when the array outgrows its capacity. Within two calls' growth
  // of that, wait until no population of it is under way and leave it: it cannot
  // move before the next call while more than one call's growth is left.
  if (capacity - bytes < 2 * growth) {
    if (beside_) wait();
    a.stopped = true;
    return;
  }
  if (a.populated > bytes + kLead / 2) return;  // still half the lead ahead
  // From the page where the populated part ends (it may hold bytes not yet
  // populated), not before the array's first whole page.
  const std::uintptr_t page = page_size();
  const std::size_t target = std::min(capacity, bytes + kLead);
  const Pages r = pages_within(std::max((at + a.populated) & ~(page - 1), at), at + target);
  a.populated = target;
  if (r.to <= r.from) return;
  if (!beside_) {
    if (!populate_pages(r)) unsupported_ = true;
    return;
  }
  if (!thread_.joinable()) {
    try {
      thread_ = std::thread([this] { run(); });
    } catch (const std::system_error&) {  // no thread to be had: nothing more (an optimization only)
      unsupported_ = true;
      return;
    }
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    pending_.push_back(r);
  }
  work_.notify_one();
}

void PopulateAhead::run() {
  for (;;) {
    Pages r;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      busy_ = false;
      idle_.notify_all();
      work_.wait(lock, [&] { return closing_ || !pending_.empty(); });
      if (pending_.empty()) return;  // closing
      r = pending_.front();
      pending_.erase(pending_.begin());
      busy_ = true;
    }
    // A failure (an old kernel) ends the population: the pages then fault as usual.
    if (!populate_pages(r)) unsupported_ = true;
  }
}

void PopulateAhead::wait() {
  if (!thread_.joinable()) return;
  std::unique_lock<std::mutex> lock(mutex_);
  idle_.wait(lock, [&] { return !busy_ && pending_.empty(); });
}

}  // namespace lepp::fast
