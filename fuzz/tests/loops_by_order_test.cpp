// SPDX-License-Identifier: GPL-3.0-or-later
// The fuzzers' open loop findings above 30 degrees (corpus/regressions/fuzz_refine/open)
// re-run under every processing order (docs/ALGORITHM.md section 7): does any
// order end them? The table it prints is docs/THEOREMS.md's "Loops by order".
// Each loop must still happen under the order it was found with (else the file
// belongs out of open/), and the verdict of every other order is checked
// against the one recorded here, so a change of any order's behaviour on these
// inputs shows up.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "lepp/fast.h"
#include "support/fuzz_input.h"

using namespace lepp;
using namespace lepp::fuzz;

namespace {

constexpr int kSeeds = 20;             // random orders 1..kSeeds
constexpr std::int64_t kBudget = 20000;  // a run that reaches it counts as a loop

struct Loop {
  const char* file;
  const char* found_with;  // the order the fuzzer found it with
  // Orders recorded as converging (fifo, lifo, flip, smallest-angle), and the
  // number of random seeds 1..kSeeds that converge.
  std::vector<std::string> converging;
  int random_converging;
};

// What the 2026-12-01 run found (docs/THEOREMS.md, "Loops by order").
const std::vector<Loop>& loops() {
  static const std::vector<Loop> v = {
      {"loop-other-centroid-theta34.1-fifo-square-in-square-b5ed5f73.bin", "fifo", {"smallest-angle"}, 0},
      {"loop-self-similar-centroid-lifo-theta32.1-right-angle-corner.bin", "lifo", {"fifo", "flip", "smallest-angle"}, 20},
      {"loop-small-angle-cascade-centroid-theta35.2-fifo-octagon-4f136fee.bin", "fifo", {}, 0},
  };
  return v;
}

FuzzInput read_input(const std::string& name) {
  const std::string path = std::string(LEPP_SOURCE_DIR) + "/corpus/regressions/fuzz_refine/open/" + name;
  std::ifstream in(path, std::ios::binary);
  const std::vector<char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  EXPECT_FALSE(bytes.empty()) << path;
  return decode(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

Outcome run(const Pslg& p, RefineOptions o, QueueOrder order, std::uint64_t seed) {
  o.order = order;
  o.order_seed = seed;
  o.max_steiner = kBudget;
  return fast::refine(p, o).outcome;
}

bool ends(Outcome o) { return o == Outcome::Converged || o == Outcome::Unimprovable; }

TEST(LoopsByOrder, EveryOpenLoopUnderEveryOrder) {
  std::printf("| loop | θ | fifo | lifo | flip | smallest-angle | random (of %d) |\n", kSeeds);
  for (const Loop& loop : loops()) {
    const FuzzInput in = read_input(loop.file);
    const Pslg p = to_pslg(in);
    const RefineOptions o = options_of(in);
    std::map<std::string, std::string> verdict;
    std::vector<std::string> converging;
    for (QueueOrder q : {QueueOrder::Fifo, QueueOrder::Lifo, QueueOrder::Flip, QueueOrder::SmallestAngle}) {
      Outcome out = run(p, o, q, 0);
      verdict[to_string(q)] = to_string(out);
      if (ends(out)) converging.push_back(to_string(q));
    }
    int random = 0;
    for (int s = 1; s <= kSeeds; ++s) random += ends(run(p, o, QueueOrder::Random, std::uint64_t(s)));
    std::printf("| %s | %g | %s | %s | %s | %s | %d converge |\n", loop.file, o.min_angle_deg, verdict["fifo"].c_str(),
                verdict["lifo"].c_str(), verdict["flip"].c_str(), verdict["smallest-angle"].c_str(), random);
    EXPECT_NE(verdict[loop.found_with], "converged") << loop.file << ": no longer loops under " << loop.found_with;
    if (loop.random_converging >= 0) {
      EXPECT_EQ(converging, loop.converging) << loop.file;
      EXPECT_EQ(random, loop.random_converging) << loop.file;
    }
  }
}

}  // namespace
