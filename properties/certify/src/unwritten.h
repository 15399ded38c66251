// SPDX-License-Identifier: GPL-3.0-or-later
// A vector whose resize leaves the new elements unwritten (std::vector value-initializes:
// a serial memset, and every fresh page faulted in, on the thread that resizes). For the
// index's arrays that ranges of a pass on several threads then fill whole.
#pragma once
#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace lepp::certify {

template <class T>
struct UnwrittenAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = UnwrittenAllocator<U>;
  };
  UnwrittenAllocator() = default;
  template <class U>
  UnwrittenAllocator(const UnwrittenAllocator<U>&) {}
  template <class U>
  void construct(U* p) {
    ::new (static_cast<void*>(p)) U;  // default-initialized: an int is left as it is
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

template <class T>
using UnwrittenVector = std::vector<T, UnwrittenAllocator<T>>;

}  // namespace lepp::certify
