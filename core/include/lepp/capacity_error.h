// SPDX-License-Identifier: GPL-3.0-or-later
// A mesh larger than an engine can number (the fast engine's ids take 29 bits,
// impl/src/capacity.h): thrown before any id would overflow, never a corrupt mesh.
// `lepp refine` prints its message on one line and exits 2, as for a request it
// cannot carry out (README, "Exit status").
#pragma once
#include <stdexcept>

namespace lepp {

class CapacityError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace lepp
