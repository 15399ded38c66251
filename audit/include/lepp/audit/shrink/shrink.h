// SPDX-License-Identifier: GPL-3.0-or-later
// Shrinking a failing input through the engine: a candidate is kept when the
// engine, run on it again, still fails the same row. Generated inputs walk
// RapidCheck's shrink tree (fewer vertices, smaller coordinates, coarser
// sampling); files use a simple greedy shrinker (drop holes, segments, vertices,
// keeping the PSLG valid).
#pragma once
#include <cstddef>
#include <functional>

#include "lepp/audit/inputs/inputs.h"
#include "lepp/pslg.h"

namespace lepp::audit {

struct ShrinkLimits {
  std::size_t max_runs = 300;   // calls of still_fails
  double max_seconds = 60;
  // Candidates tried at once (-j): the next `jobs` edits in the one-at-a-time order,
  // each on the current input; the first of them that still fails is kept, which
  // is the edit a one-at-a-time search keeps (those before it passed), so the
  // result does not depend on jobs, only the runs spent. still_fails must then be
  // safe to call from several threads.
  std::size_t jobs = 1;
};

struct ShrinkResult {
  Pslg pslg;                // validated: the smallest still failing
  std::size_t steps = 0;    // accepted shrinks
  std::size_t runs = 0;     // calls of still_fails
};

// still_fails gets validated PSLGs only.
ShrinkResult shrink_input(const AuditInput& input, const std::function<bool(const Pslg&)>& still_fails,
                          const ShrinkLimits& limits);

// The greedy shrinker alone (for any PSLG).
ShrinkResult shrink_pslg(const Pslg& validated, const std::function<bool(const Pslg&)>& still_fails,
                         const ShrinkLimits& limits);

}  // namespace lepp::audit
