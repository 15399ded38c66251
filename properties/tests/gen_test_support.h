// SPDX-License-Identifier: GPL-3.0-or-later
// What the generators' tests share: a generated PSLG must validate untouched.
#pragma once
#include <rapidcheck.h>

#include <exception>
#include <string>
#include <vector>

#include "lepp/pslg.h"
#include "lepp/validate.h"

namespace lepp::test {

// The PSLG validates with its vertices and segments as generated; each warning
// validate gives must be one `allowed` admits (none when it is null).
inline void expect_validates_untouched(const Pslg& p, bool (*allowed)(const std::string& warning) = nullptr) {
  RC_TAG(p.source);
  std::vector<std::string> warnings;
  Pslg v;
  try {
    v = validate(p, warnings);
  } catch (const std::exception& e) {
    RC_FAIL(std::string("validate rejected a generated PSLG: ") + e.what());
  }
  for (const std::string& w : warnings) RC_ASSERT(allowed && allowed(w));
  RC_ASSERT(v.vertices.size() == p.vertices.size());
  RC_ASSERT(v.segments.size() == p.segments.size());
}

}  // namespace lepp::test
