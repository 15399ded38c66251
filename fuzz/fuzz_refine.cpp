// SPDX-License-Identifier: GPL-3.0-or-later
// fuzz_refine: a structure-aware hunt for loops. The input is a PSLG on a small
// grid plus theta, method, engine and queue order (support/fuzz_input.h). The
// run gets a loop guard justified by the input (support/loop_guard.h); a run
// that stops on it is a loop, re-run with a trace, classified and reported.
// A run that ends is certified.
//
// Environment: LEPP_FUZZ_METHOD, LEPP_FUZZ_THETA=lo:hi pin the method and the
// theta band; LEPP_FUZZ_MIN_INPUT_ANGLE=60 skips PSLGs with a smaller angle
// between segments; LEPP_FUZZ_IGNORE=class,... keeps fuzzing past known classes.
// A loop outside the paper's claims (support/known_loops.h: midpoint above
// alpha_limit, centroid above 30, small input angles) is printed, kept once per
// class and band in LEPP_FUZZ_KNOWN_DIR, and the run goes on; any other loop,
// an exception or an uncertified mesh stops it.
#include <cstdint>
#include <optional>
#include <cstdlib>
#include <stdexcept>

#include <fmt/format.h>

#include "lepp/engines/registry.h"
#include "lepp/io.h"
#include "support/certify_result.h"
#include "support/finding.h"
#include "support/fuzz_input.h"
#include "support/known_loops.h"
#include "support/loop_guard.h"
#include "support/pslg_mutator.h"

using namespace lepp::fuzz;
using lepp::engines::Engine;

namespace {
constexpr std::int64_t kBudgetCap = 200000;  // keeps one execution under a few seconds

void finding(const std::string& cls, const std::string& what) { report_finding("fuzz_refine", cls, what); }
}  // namespace

LEPP_FUZZ_PSLG_MUTATOR

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzInput input = decode(data, size);
  apply_environment(input);
  const Engine engine = input.engine == 1 ? Engine::Reference : Engine::Fast;
  const std::optional<lepp::Pslg> valid = valid_pslg(input);
  if (!valid) return 0;
  const lepp::Pslg& pslg = *valid;
  if (const char* min = std::getenv("LEPP_FUZZ_MIN_INPUT_ANGLE"))
    if (input_features(pslg).min_input_angle_deg < std::atof(min)) return 0;

  lepp::RefineOptions options = options_of(input);
  const LoopGuard guard = loop_guard(pslg, engine == Engine::Fast ? kBudgetCap : kBudgetCap / 20);
  options.max_steiner = guard.steiner_budget;
  options.edge_floor = guard.edge_floor;
  const std::string what = fmt::format("{} engine={} budget={} floor={}", describe(input), to_string(engine),
                                       guard.steiner_budget, guard.edge_floor);
  lepp::RefineResult result;
  try {
    result = refine(engine, pslg, options);
  } catch (const std::exception& e) {
    finding("engine-exception", fmt::format("{}: {}", what, e.what()));
    return 0;
  }
  // A known class (outside the paper's claims, or documented in THEOREMS.md): one example
  // kept per class and band, baked (method and theta as pinned) so it replays without the
  // environment, and the run goes on. Encoded only then: not on every execution.
  auto keep_known = [&](const std::string& cls, const std::string& reason, const std::string& message) {
    const std::vector<std::uint8_t> baked = encode(input);
    report_known_finding("fuzz_refine", cls, reason, known_finding_key("fuzz_refine", cls, options.method, options.min_angle_deg),
                         message, baked.data(), baked.size());
  };
  if (std::string problems = certify_result(pslg, options, result); !problems.empty()) {
    const std::string message = fmt::format("{} outcome={}: {}", what, lepp::to_string(result.outcome), problems);
    if (precision_undecided(problems))
      keep_known("precision-undecided", "tie-search-bound", message);
    else
      finding("not-certified", message);
  }
  if (result.outcome == lepp::Outcome::SteinerBudget || result.outcome == lepp::Outcome::EdgeFloor) {
    options.trace = true;
    const lepp::RefineResult traced = refine(engine, pslg, options);
    const std::string cls = classify_loop(pslg, options, traced);
    const std::string message = fmt::format("{} band={} outcome={} steiner={} stuck={}", what,
                                            theta_band(options.min_angle_deg), lepp::to_string(result.outcome),
                                            result.steiner_points, result.stuck);
    // Outside the paper's claims, or on an input doubles do not resolve (THEOREMS.md,
    // "Termination in doubles").
    std::string reason = unclaimed_loop_reason(options.method, options.min_angle_deg, cls);
    if (reason.empty()) reason = below_resolution_reason(pslg);
    if (!reason.empty())
      keep_known("loop-" + cls, reason, message);
    else
      finding("loop-" + cls, message);
  }
  return 0;
}
