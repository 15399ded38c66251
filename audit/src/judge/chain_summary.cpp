// SPDX-License-Identifier: GPL-3.0-or-later
// Whether a conformance failure's chain is one consistent variant (judge/chain_summary.h).
#include "judge/chain_summary.h"

namespace lepp::audit {

Deviation deviation_named(const std::string& name) {
  for (int k = 0; k < kDeviations; ++k)
    if (name == to_string(static_cast<Deviation>(k))) return static_cast<Deviation>(k);
  return Deviation::Unknown;
}

bool fits_one_variant(const ConformanceFailure& f) {
  return f.chain_complete && f.chain.size() == 1 && has_variant(deviation_named(f.deviation));
}

}  // namespace lepp::audit
