// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind pslg_mutator.h: the LLVMFuzzerCustomMutator shared by the
// structure-aware targets.
#include "pslg_mutator.h"

#include <algorithm>
#include <cstring>
#include <random>

#include "fuzz_input.h"

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);

namespace lepp::fuzz {

std::size_t mutate_pslg_bytes(std::uint8_t* data, std::size_t size, std::size_t max_size, unsigned seed) {
  std::mt19937 rng(seed);
  if (rng() % 8 == 0) return LLVMFuzzerMutate(data, size, max_size);
  FuzzInput input = decode(data, size);
  const int edits = 1 + static_cast<int>(rng() % 3);
  for (int i = 0; i < edits; ++i) mutate(input, rng);
  const std::vector<std::uint8_t> bytes = encode(input);
  if (bytes.size() > max_size) return size;
  std::memcpy(data, bytes.data(), bytes.size());
  return bytes.size();
}

}  // namespace lepp::fuzz
