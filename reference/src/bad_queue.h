// SPDX-License-Identifier: GPL-3.0-or-later
// The reference engine's queue of bad triangles and its processing orders
// (ALGORITHM.md section 7), written from that page alone: the fast engine has
// its own. One interface (push a batch, pop the next), one policy per order.
#pragma once
#include <algorithm>
#include <cstdint>
#include <deque>
#include <queue>
#include <vector>

#include "triangulation.h"

namespace lepp::reference::detail {

// A member of a batch: the triangle's key (ids sorted) and, for the
// smallest-angle order only, sin^2 of its smallest angle (exact).
struct Queued {
  Tri key;
  FT sin2;
};

// sin^2 of f's smallest angle: cross^2 over the largest product of two squared
// edge lengths (the two sides of the smallest angle), as an exact rational.
inline FT smallest_angle_sin2(FH f) {
  const CPoint &a = f->vertex(0)->point(), &b = f->vertex(1)->point(), &c = f->vertex(2)->point();
  FT cross = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
  FT ab = CGAL::squared_distance(a, b), ac = CGAL::squared_distance(a, c), bc = CGAL::squared_distance(b, c);
  FT m = std::max({ab * ac, ab * bc, ac * bc});
  return cross * cross / m;
}

class BadQueue {
 public:
  BadQueue(QueueOrder order, std::uint64_t seed) : order_(order), state_(seed) {}

  // The initial queue (initial = true) or an insertion's batch. The batch comes
  // in creation order; every order but flip's batches starts from key order.
  void push(std::vector<Queued>& batch, bool initial) {
    if (order_ != QueueOrder::Flip || initial)
      std::sort(batch.begin(), batch.end(), [](const Queued& x, const Queued& y) { return x.key < y.key; });
    switch (order_) {
      case QueueOrder::Fifo:
      case QueueOrder::Flip:
      case QueueOrder::Batch:  // runs in rounds (refine.cpp), not through this queue
        for (const Queued& q : batch) fifo_.push_back(q.key);
        break;
      case QueueOrder::Lifo:  // at the front, smallest key first
        for (auto it = batch.rbegin(); it != batch.rend(); ++it) fifo_.push_front(it->key);
        break;
      case QueueOrder::Random:  // Fisher-Yates from the back, then at the back
        for (std::size_t i = batch.size(); i > 1; --i) std::swap(batch[i - 1], batch[draw() % i]);
        for (const Queued& q : batch) fifo_.push_back(q.key);
        break;
      case QueueOrder::SmallestAngle:
        for (const Queued& q : batch) heap_.push(q);
        break;
    }
  }

  bool empty() const { return order_ == QueueOrder::SmallestAngle ? heap_.empty() : fifo_.empty(); }

  Tri pop() {
    Tri t;
    if (order_ == QueueOrder::SmallestAngle) {
      t = heap_.top().key;
      heap_.pop();
    } else {
      t = fifo_.front();
      fifo_.pop_front();
    }
    return t;
  }

 private:
  // SplitMix64, one draw.
  std::uint64_t draw() {
    state_ += 0x9e3779b97f4a7c15ULL;
    std::uint64_t z = state_;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  // std::priority_queue pops the largest: x < y iff y comes first.
  struct Later {
    bool operator()(const Queued& x, const Queued& y) const {
      if (x.key == y.key) return false;
      if (y.sin2 != x.sin2) return y.sin2 < x.sin2;
      return y.key < x.key;
    }
  };

  QueueOrder order_;
  std::uint64_t state_;
  std::deque<Tri> fifo_;
  std::priority_queue<Queued, std::vector<Queued>, Later> heap_;
};

}  // namespace lepp::reference::detail
