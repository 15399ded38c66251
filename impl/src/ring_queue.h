// SPDX-License-Identifier: GPL-3.0-or-later
// A double-ended queue in fixed blocks: push at either end, pop at the front,
// index from the front. A block emptied at the front is kept for the next one
// needed (a few at most), so a refinement in steady state allocates nothing
// (std::deque allocates a block every few dozen pushes). Blocks, not one ring
// buffer grown by doubling: the memory follows the queue's size, and growing
// copies nothing (a ring held up to twice the largest size, and both rings while
// it grew: 3.4 bytes a triangle of the peak at 10^7 triangles, issue 40).
#pragma once
#include <cstddef>
#include <deque>
#include <memory>
#include <utility>
#include <vector>

namespace lepp::fast {

template <class T>
class RingQueue {
 public:
  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  const T& operator[](std::size_t i) const {
    const std::size_t at = head_ + i;
    if (at < kBlock) return blocks_.front()[at];  // the front block: no deque index (the queue's prefetch)
    return blocks_[at / kBlock][at % kBlock];
  }
  const T& front() const { return blocks_.front()[head_]; }
  void pop_front() {
    --size_;
    if (++head_ == kBlock) {
      retire(std::move(blocks_.front()));
      blocks_.pop_front();
      head_ = 0;
    }
  }
  void push_back(const T& x) {
    // No block lies past the one holding slot `at`: a new one is needed only at a
    // block's start, and otherwise `at` is in the back block (no deque index).
    const std::size_t at = head_ + size_;
    if (at % kBlock == 0 && at / kBlock == blocks_.size()) blocks_.push_back(fresh());
    blocks_.back()[at % kBlock] = x;
    ++size_;
  }
  void push_front(const T& x) {
    if (head_ == 0) {
      blocks_.push_front(fresh());
      head_ = kBlock;
    }
    --head_;
    blocks_.front()[head_] = x;
    ++size_;
  }

 private:
  static constexpr std::size_t kBlock = std::size_t{1} << 13;  // 64 KiB of 8-byte items
  static constexpr std::size_t kSpares = 2;
  using Block = std::unique_ptr<T[]>;
  Block fresh() {
    if (spare_.empty()) return Block(new T[kBlock]);
    Block b = std::move(spare_.back());
    spare_.pop_back();
    return b;
  }
  void retire(Block b) {
    if (spare_.size() < kSpares) spare_.push_back(std::move(b));
  }
  // blocks_[0][head_] is the front; the queue fills the blocks in order.
  std::deque<Block> blocks_;
  std::vector<Block> spare_;
  std::size_t head_ = 0, size_ = 0;
};

}  // namespace lepp::fast
