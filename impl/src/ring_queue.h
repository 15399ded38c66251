// SPDX-License-Identifier: GPL-3.0-or-later
// A double-ended queue in one ring buffer: push at either end, pop at the
// front, index from the front. Grows by doubling, never shrinks, so a
// refinement in steady state allocates nothing (std::deque allocates a block
// every few dozen pushes).
#pragma once
#include <cstddef>
#include <vector>

namespace lepp::fast {

template <class T>
class RingQueue {
 public:
  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  const T& operator[](std::size_t i) const { return buf_[(head_ + i) & mask_]; }
  const T& front() const { return buf_[head_]; }
  void pop_front() {
    head_ = (head_ + 1) & mask_;
    --size_;
  }
  void push_back(const T& x) {
    if (size_ == buf_.size()) grow();
    buf_[(head_ + size_) & mask_] = x;
    ++size_;
  }
  void push_front(const T& x) {
    if (size_ == buf_.size()) grow();
    head_ = (head_ + mask_) & mask_;
    buf_[head_] = x;
    ++size_;
  }

 private:
  void grow() {
    std::vector<T> next(buf_.empty() ? 1024 : 2 * buf_.size());
    for (std::size_t i = 0; i < size_; ++i) next[i] = (*this)[i];
    buf_.swap(next);
    head_ = 0;
    mask_ = buf_.size() - 1;
  }
  std::vector<T> buf_;
  std::size_t head_ = 0, size_ = 0, mask_ = 0;
};

}  // namespace lepp::fast
