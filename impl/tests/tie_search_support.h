// SPDX-License-Identifier: GPL-3.0-or-later
// What the tests of the tie search's bound share (tie_search_bound_test.cpp,
// tie_search_4096_test.cpp): the precision corpus, the options at a bound, the
// strict certificate at a bound, and its claims by outcome.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "lepp/certify.h"
#include "lepp/input.h"
#include "lepp/refine.h"
#include "lepp/validate.h"

namespace lepp::tie_search_test {

inline const std::string kPrecision = LEPP_SOURCE_DIR "/corpus/regressions/precision/";

inline Pslg load(const std::string& file) {
  std::vector<std::string> warnings;
  return validate(read_input(kPrecision + file, warnings), DomainOptions{}, warnings);
}

inline RefineOptions options(double theta, Method method, std::size_t states) {
  RefineOptions o;
  o.min_angle_deg = theta;
  o.method = method;
  o.tie_search_states = states;
  return o;
}

// The strict certificate at theta (the engine's list held to the certifier's rules) at `states`.
inline certify::Report certificate(const Pslg& pslg, const RefineResult& r, double theta, Method method, std::size_t states) {
  certify::Options o;
  o.min_angle_deg = theta;
  o.unimprovable = r.unimprovable;
  o.precision_method = method;
  o.tie_search_states = states;
  return certify::certify(pslg, r.mesh, o);
}

inline std::size_t count(const certify::Report& rep, certify::PrecisionOutcome outcome) {
  std::size_t n = 0;
  for (const certify::PrecisionClaim& c : rep.precision_claims) n += c.outcome == outcome;
  return n;
}

}  // namespace lepp::tie_search_test
