// SPDX-License-Identifier: GPL-3.0-or-later
// The batch order's next queue (docs/ALGORITHM.md section 7, "batch"): the entries
// that wait, in the round's order, then the members' batches; each triangle once, at
// its first place; none that is gone. The rest of a queue that a round never read is
// moved as it is, so the one triangle that can be in it and in a batch too (the
// triangle a split off its line keeps, section 6) needs the rest read for the marks.
// No corpus or fuzz input found so far makes that triangle wait in the rest and be
// looked at twice (tools/mutation/notes.md), so the function is tested here directly.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "batch_rounds.h"

namespace lepp::fast {
namespace {

TriMesh slots(int n) {
  TriMesh m;
  m.stamp.assign(static_cast<std::size_t>(n), 0);
  return m;
}

std::vector<Item> items(const std::vector<int>& tris) {
  std::vector<Item> out;
  for (int t : tris) out.push_back({t, 0});
  return out;
}

std::vector<Keyed> batches(const std::vector<Item>& its) {
  std::vector<Keyed> out;
  for (const Item& it : its) {
    Keyed k{};
    k.item = it;
    out.push_back(k);
  }
  return out;
}

std::vector<int> tris(const std::vector<Item>& q) {
  std::vector<int> out;
  for (const Item& it : q) out.push_back(it.tri);
  return out;
}

struct Queue {
  TriMesh mesh = slots(16);
  RoundMarks queued;
  std::vector<Item> out;
  std::vector<Item> next(const std::vector<Item>& round, std::size_t rest, const std::vector<Item>& waiting,
                         const std::vector<Item>& batch, bool kept) {
    next_round_queue(mesh, round, rest, waiting, batches(batch), kept, queued, out);
    return out;
  }
};

TEST(BatchNextRound, WaitingThenTheRestAsItIsThenTheBatches) {
  Queue q;
  const auto out = q.next(items({0, 1, 2, 3, 4}), 3, items({1, 0}), items({5, 6}), false);
  EXPECT_EQ(tris(out), (std::vector<int>{1, 0, 3, 4, 5, 6}));
}

TEST(BatchNextRound, ATriangleInTwoBatchesComesOnceAtItsFirstPlace) {
  Queue q;
  // 1 waits and is in a batch too (a member that stays, or its kept triangle).
  const auto out = q.next(items({0, 1, 2}), 3, items({1}), items({7, 1, 8, 7}), false);
  EXPECT_EQ(tris(out), (std::vector<int>{1, 7, 8}));
}

TEST(BatchNextRound, AKeptTriangleThatWaitsInTheRestComesOnce) {
  Queue q;
  // Triangle 3 waits in the rest (the round ended before it) and a member's split
  // off its line kept it (it is in that member's batch): once, in the rest's place.
  const auto out = q.next(items({0, 1, 2, 3, 4}), 2, items({1}), items({8, 3, 9}), true);
  EXPECT_EQ(tris(out), (std::vector<int>{1, 2, 3, 4, 8, 9}));
}

TEST(BatchNextRound, GoneTrianglesAreLeftOut) {
  Queue q;
  ++q.mesh.stamp[0];  // the waiting 0 is gone
  ++q.mesh.stamp[5];  // the rest's 5 is gone, and a batch holds the new triangle in its slot
  ++q.mesh.stamp[9];  // the batch's 9 is gone
  std::vector<Item> batch = items({5, 9, 6});
  batch[0].stamp = 1;
  const auto out = q.next(items({0, 1, 5}), 2, items({0, 1}), batch, true);
  // The rest moves as it is (its gone entry is dropped when read); the new triangle
  // in slot 5 is not the rest's, so it is taken.
  EXPECT_EQ(tris(out), (std::vector<int>{1, 5, 5, 6}));
  EXPECT_EQ(out[1].stamp, 0u);
  EXPECT_EQ(out[2].stamp, 1u);
}

TEST(BatchNextRound, EachCallIsItsOwnRound) {
  Queue q;
  q.next(items({0, 1}), 2, items({0, 1}), {}, false);
  // The marks of the call before do not carry over.
  const auto out = q.next(items({0, 1}), 2, items({1, 0}), {}, false);
  EXPECT_EQ(tris(out), (std::vector<int>{1, 0}));
}

}  // namespace
}  // namespace lepp::fast
