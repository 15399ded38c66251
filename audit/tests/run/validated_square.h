// SPDX-License-Identifier: GPL-3.0-or-later
// The input the command adapter's tests hand to the programs they run: a 4 x 4
// square, validated. Shared by adapter_test.cpp and shell_words_test.cpp.
#pragma once
#include <string>
#include <vector>

#include "lepp/pslg.h"
#include "lepp/validate.h"

namespace lepp::audit_test {

inline Pslg validated_square() {
  Pslg p;
  p.vertices = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  p.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  std::vector<std::string> warnings;
  return validate(p, warnings);
}

}  // namespace lepp::audit_test
