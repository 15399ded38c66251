// SPDX-License-Identifier: GPL-3.0-or-later
// Shared by the hostile-input tests: run the engines that exist on a validated
// PSLG and certify what they give.
#pragma once
#include <string>
#include <vector>

#include "lepp/pslg.h"
#include "lepp/refine.h"

namespace lepp::hostile {

// What a hostile case may end in. A guard outcome is an honest stop, but only
// where the case says it may happen.
enum class Expect { Converge, AnyOutcome };

struct EngineRun {
  std::string engine;  // the registry's name
  RefineResult result;
};

// Refines with each of lepp's engines in the registry (the reference only when
// `reference`), each with `options`.
std::vector<EngineRun> run_engines(const Pslg& validated, const RefineOptions& options, bool reference = true);

// Certifies a result: a valid CDT of the domain always, and the angle bound
// (with the engine's unimprovable list) when the run did not stop on a guard.
// Adds a GoogleTest failure with the certifier's report when it fails. Without
// the certifier (not built), only ids, input vertices and non-emptiness are checked.
void expect_certified(const Pslg& validated, const EngineRun& run, double theta, const std::string& what);

// True when the outcome is not a guard stop.
bool finished(Outcome outcome);

}  // namespace lepp::hostile
