// SPDX-License-Identifier: GPL-3.0-or-later
// The fast engine's compact storage (issue 40: the peak memory): a triangle's flags
// and longest-edge cache in its vertex words, the queue in blocks, the Steiner
// points' segments as a bit each and a sorted list. Each against the plain
// structure it replaces, on fixed-seed sequences of operations.
#include <gtest/gtest.h>

#include <cstdint>
#include <deque>
#include <random>
#include <vector>

#include "bad_queue.h"
#include "ring_queue.h"
#include "tri_mesh.h"

namespace lepp::fast {
namespace {

TEST(CompactStorage, TriangleKeepsIdsFlagsAndLongestApart) {
  const int big = (1 << 29) - 1;  // the largest vertex id a triangle holds
  std::mt19937 rng(40);
  for (int round = 0; round < 2000; ++round) {
    int v[3], n[3];
    std::int8_t s[3];
    for (int i = 0; i < 3; ++i) {
      v[i] = round < 8 ? big - i : static_cast<int>(rng() % (static_cast<unsigned>(big) + 1));
      n[i] = static_cast<int>(rng() % 1000) - 1;
      s[i] = rng() % 2 ? 0 : -1;
    }
    const int longest = static_cast<int>(rng() % 4) - 1;
    FTri f(v, n, s, longest);
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(f.v(i), v[i]);
      EXPECT_EQ(f.seg(i), s[i]);
      EXPECT_EQ(f.nbr[i], n[i]);
    }
    EXPECT_EQ(f.longest(), longest);
    // Each setter changes its own field only.
    const int l2 = static_cast<int>(rng() % 3);
    f.set_longest(l2);
    const int k = static_cast<int>(rng() % 3);
    const std::int8_t flipped = s[k] < 0 ? 0 : -1;
    f.set_seg(k, flipped);
    s[k] = flipped;
    const int j = static_cast<int>(rng() % 3);
    v[j] = static_cast<int>(rng() % (static_cast<unsigned>(big) + 1));
    f.set_v(j, v[j]);
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(f.v(i), v[i]);
      EXPECT_EQ(f.seg(i), s[i]);
    }
    EXPECT_EQ(f.longest(), l2);
    f.set_longest(-1);
    EXPECT_EQ(f.longest(), -1);
    EXPECT_EQ(f.v(0), v[0]);
  }
}

TEST(CompactStorage, BlockQueueIsADeque) {
  std::mt19937 rng(7);
  RingQueue<Item> q;
  std::deque<Item> model;
  std::uint32_t next = 0;
  // Phases that grow the queue by pushes at either end, then drain it, so that
  // blocks fill, empty, are reused and are added at the front.
  for (int phase = 0; phase < 12; ++phase) {
    const unsigned push_weight = phase % 3 == 2 ? 1 : 3;
    for (int step = 0; step < 40000; ++step) {
      const unsigned r = rng() % (push_weight + 1);
      if (r < push_weight) {
        const Item it{static_cast<int>(next), next};
        ++next;
        if (rng() % (phase % 2 ? 2 : 8) == 0) {
          q.push_front(it);
          model.push_front(it);
        } else {
          q.push_back(it);
          model.push_back(it);
        }
      } else if (!model.empty()) {
        ASSERT_EQ(q.front().tri, model.front().tri);
        q.pop_front();
        model.pop_front();
      }
      ASSERT_EQ(q.size(), model.size());
      ASSERT_EQ(q.empty(), model.empty());
      if (!model.empty()) {
        const std::size_t i = rng() % model.size();
        ASSERT_EQ(q[i].tri, model[i].tri) << "index " << i << " of " << model.size();
        ASSERT_EQ(q[i].stamp, model[i].stamp);
      }
    }
    while (phase % 4 == 3 && !model.empty()) {
      ASSERT_EQ(q.front().tri, model.front().tri);
      q.pop_front();
      model.pop_front();
    }
  }
}

TEST(CompactStorage, SteinerSegmentsAsBitsAndAList) {
  Pslg pslg;
  pslg.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  pslg.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  SegmentMembership mem = make_membership(pslg);
  std::vector<int> plain;  // what the int per Steiner point held
  std::mt19937 rng(3);
  for (int k = 0; k < 5000; ++k) {
    const int s = rng() % 5 == 0 ? static_cast<int>(rng() % 4) : -1;
    mem.add_steiner(s);
    plain.push_back(s);
  }
  const int n = mem.input_vertices;
  for (int k = 0; k < static_cast<int>(plain.size()); ++k) {
    const int v = n + k;
    EXPECT_EQ(mem.steiner_segment(v), plain[static_cast<std::size_t>(k)]) << "Steiner point " << k;
    EXPECT_EQ(mem.on_any(v), plain[static_cast<std::size_t>(k)] >= 0);
    std::vector<int> seen;
    mem.for_each(v, [&](int s) { seen.push_back(s); });
    EXPECT_EQ(seen, plain[static_cast<std::size_t>(k)] >= 0 ? std::vector<int>{plain[static_cast<std::size_t>(k)]} : std::vector<int>{});
    // An edge from a Steiner point to an input vertex: the Steiner point's segment.
    EXPECT_EQ(mem.segment_of(v, 0), plain[static_cast<std::size_t>(k)]);
    EXPECT_EQ(mem.segment_of(0, v), plain[static_cast<std::size_t>(k)]);
  }
  EXPECT_EQ(mem.segment_of(1, 2), 1);
  EXPECT_EQ(mem.segment_of(0, 2), -1);
}

}  // namespace
}  // namespace lepp::fast
