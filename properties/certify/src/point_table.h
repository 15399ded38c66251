// SPDX-License-Identifier: GPL-3.0-or-later
// Points by value, for the passes that ask of millions of mesh vertices whether a point
// is among a set: an open-addressing table of ids, a power of two at least twice their
// number, probed linearly from the hash's high bits (mixed once more: PointHash's low
// bits are the coordinates' low bits). No division and no list per bucket, where
// std::unordered_map has both. Equal as Point's == compares: -0 is 0, NaN is nothing.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "certification.h"

namespace lepp::certify {

class PointTable {
 public:
  explicit PointTable(std::size_t ids) {
    while (size_ < 2 * ids) size_ *= 2, ++bits_;
    slot_.assign(size_, -1);
  }
  // Where p's probe starts: asked ahead for the loads a pass makes (prefetch_write).
  const int* home_slot(const Point& p) const { return &slot_[home(p)]; }
  // The slot of the id whose point equals p (point_of(id)), else the empty slot where
  // p's id goes: a negative id there.
  template <class PointOf>
  int& slot(const Point& p, PointOf&& point_of) {
    return slot_[probe(p, point_of)];
  }
  // The id whose point equals p, or -1.
  template <class PointOf>
  int find(const Point& p, PointOf&& point_of) const {
    return slot_[probe(p, point_of)];
  }

 private:
  template <class PointOf>
  std::size_t probe(const Point& p, PointOf&& point_of) const {
    std::size_t k = home(p);
    while (slot_[k] >= 0 && !(point_of(slot_[k]) == p)) k = (k + 1) & (size_ - 1);
    return k;
  }
  std::size_t home(const Point& p) const {
    return static_cast<std::size_t>((PointHash()(p) * 0x9E3779B97F4A7C15ull) >> (64 - bits_));
  }
  std::size_t size_ = 16;
  int bits_ = 4;
  std::vector<int> slot_;
};

}  // namespace lepp::certify
