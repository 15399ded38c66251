// SPDX-License-Identifier: GPL-3.0-or-later
// Private to the reference engine: the longest edge of each face met so far, by the
// face's ids (sorted), kept as the id of the vertex opposite it. The edge order is a
// function of the ids and of their coordinates, which never change, so an answer
// stays true across flips (faces with a bounding-box corner, id -1, are not kept).
// An open-addressing table (a power of two at least twice the faces kept, probed
// linearly from the hash's high bits): std::unordered_map allocated a node per face,
// 8 % of fuzz_differential under ASan (its allocations' stack traces).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace lepp::reference::detail {

class LongestEdgeMemo {
 public:
  using Ids = std::array<int, 3>;  // sorted, each >= 0 (lepp::Tri)

  // The answer kept for face ids t, or a new slot holding -1 for the caller to fill
  // (valid until the next call).
  int& at(const Ids& t) {
    if (2 * (used_ + 1) > slots_.size()) grow();
    Slot& s = slots_[probe(t)];
    if (s.ids[0] < 0) s.ids = t, s.answer = -1, ++used_;
    return s.answer;
  }
  std::size_t size() const { return used_; }

 private:
  struct Slot {
    Ids ids{-1, -1, -1};  // ids[0] < 0: empty
    int answer = -1;
  };
  std::size_t probe(const Ids& t) const {
    const std::uint64_t h = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(t[0])) * 0x9E3779B97F4A7C15ull) ^
                            (static_cast<std::uint64_t>(static_cast<std::uint32_t>(t[1])) << 21) ^
                            static_cast<std::uint64_t>(static_cast<std::uint32_t>(t[2]));
    std::size_t k = static_cast<std::size_t>((h * 0x9E3779B97F4A7C15ull) >> (64 - bits_));
    while (slots_[k].ids[0] >= 0 && slots_[k].ids != t) k = (k + 1) & (slots_.size() - 1);
    return k;
  }
  void grow() {
    std::vector<Slot> old;
    old.swap(slots_);
    ++bits_;
    slots_.assign(std::size_t{1} << bits_, Slot{});
    for (const Slot& s : old)
      if (s.ids[0] >= 0) slots_[probe(s.ids)] = s;
  }
  std::vector<Slot> slots_;
  std::size_t used_ = 0;
  int bits_ = 5;  // the first grow() makes 64 slots
};

}  // namespace lepp::reference::detail
