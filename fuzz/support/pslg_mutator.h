// SPDX-License-Identifier: GPL-3.0-or-later
// The LLVMFuzzerCustomMutator shared by the structure-aware targets: decode the
// bytes to a FuzzInput, apply one to three structural edits (or, now and then,
// libFuzzer's own byte mutation), and encode the result back.
#pragma once
#include <cstddef>
#include <cstdint>

namespace lepp::fuzz {
std::size_t mutate_pslg_bytes(std::uint8_t* data, std::size_t size, std::size_t max_size, unsigned seed);
}

#define LEPP_FUZZ_PSLG_MUTATOR                                                                              \
  extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t max_size, \
                                                 unsigned int seed) {                                        \
    return lepp::fuzz::mutate_pslg_bytes(data, size, max_size, seed);                                        \
  }
