// SPDX-License-Identifier: GPL-3.0-or-later
// A failure's signature: what a shrunk input must still fail with.
#include "lepp/audit/judge/signature.h"

#include <fmt/format.h>

#include "lepp/gen.h"

namespace lepp::audit {

std::string conformance_deviation(const RowResult& result) { return result.deviation; }

FailureSignature failure_signature(Row row, const Pslg& input, const EngineRun& run, const RowResult& result) {
  FailureSignature s;
  s.verdict = result.verdict;
  // An internal error of the audit keeps candidates on which the same stage stops.
  if (result.verdict == Verdict::InternalError) {
    s.kind = "internal-error in the " + result.internal_error;
    return s;
  }
  auto first_reason = [&] { return result.violations.empty() ? std::string() : certify::to_string(result.violations.front().reason); };
  switch (row) {
    case Row::Certificate:
      // The program's arithmetic named first (arithmetic.h): a shrunk input must show it too.
      if (run.status == RunStatus::Ok) s.kind = result.deviation.empty() ? first_reason() : result.deviation + ", " + first_reason();
      else if (run.status == RunStatus::Crashed) s.kind = run.signal ? fmt::format("crashed: signal {}", run.signal) : "crashed";
      else if (run.status == RunStatus::ExitCode) s.kind = fmt::format("exit status {}", run.exit_code);
      else s.kind = to_string(run.status);
      break;
    case Row::MinAngle:
      s.kind = result.deviation.empty() ? first_reason() : result.deviation + ", " + first_reason();
      s.well_shaped = gen::min_input_angle_deg(input) >= 60;
      break;
    case Row::Theorem2: s.kind = first_reason(); break;
    case Row::Termination: s.kind = to_string(run.status); break;
    case Row::Conformance: s.kind = conformance_deviation(result); break;
  }
  return s;
}

bool keeps(const FailureSignature& original, const FailureSignature& candidate) {
  if (candidate.verdict != original.verdict || candidate.kind != original.kind) return false;
  return !original.well_shaped || candidate.well_shaped;
}

std::string FailureSignature::text() const {
  std::string t = kind.empty() ? to_string(verdict) : kind;
  if (well_shaped) t += " (input angles >= 60 degrees)";
  return t;
}

}  // namespace lepp::audit
