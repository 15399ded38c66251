// SPDX-License-Identifier: GPL-3.0-or-later
// The audit's rows: one statement of the paper each, decided for one run of the
// engine on one input. The certificate, angle and Theorem 2 rows reuse the
// exact certifier (lepp::certify); conformance replays the trace on the exact
// reference (lepp/audit/judge/conformance.h) when that checker is built in.
#pragma once
#include <array>
#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "lepp/audit/judge/conformance.h"
#include "lepp/audit/engine.h"
#include "lepp/certify.h"

namespace lepp::audit {

struct StepDiagnosis;  // lepp/audit/judge/diagnosis.h

enum class Row { Certificate, MinAngle, Theorem2, Termination, Conformance };
constexpr std::size_t kRows = 5;
constexpr std::array<Row, kRows> kAllRows = {Row::Certificate, Row::MinAngle, Row::Theorem2, Row::Termination,
                                             Row::Conformance};

const char* row_key(Row row);        // "certificate", "min-angle", "theorem-2", "termination", "conformance"
const char* row_statement(Row row);  // what is checked, one line
const char* row_passage(Row row);    // the paper passage it comes from

enum class Verdict {
  Held,           // the statement holds for this run
  Failed,         // it does not: a counterexample
  Finding,        // outside what the paper claims (a non-ending run above the termination band): reported, not failed
  NotApplicable,  // the statement says nothing here (no mesh to check, an input outside its class)
  NotChecked,     // could be checked but this build cannot (no trace, no conformance checker)
  // The audit's own verdict code (the certifier, the conformance replay, the
  // step's diagnosis) stopped with an exception on this run: undecided, and a
  // failure of the audit, not of the program (issue 30). Saved as an
  // internal-error finding; the audit's exit status is 3.
  InternalError,
};
const char* to_string(Verdict v);

struct RowResult {
  Verdict verdict = Verdict::NotChecked;
  std::string detail;                         // one line: the first violation, why not applicable, ...
  std::vector<certify::Violation> violations; // what to mark in the picture
  // Conformance failures: the named deviation (ConformanceFailure::deviation);
  // empty for the other rows. Same name, same bug: shrinking keeps it.
  std::string deviation;
  long step = 0;  // conformance, stepwise Theorem 2: the failing step, 1-based (0: not a step finding)
  // A step finding's picture and words (lepp/audit/judge/diagnosis.h); null otherwise.
  std::shared_ptr<const StepDiagnosis> diagnosis;
  // Conformance: every traced step fits the deviation's variant (ConformanceFailure::consistent_variant).
  bool consistent_variant = false;
  // Conformance: every deviation of the trace (ConformanceFailure::chain); the first is `deviation`.
  std::vector<DeviationLink> deviations;
  // Conformance under --arithmetic double: steps accepted only under that reading, by name.
  std::map<std::string, std::size_t> inexact_steps;
  // InternalError: where the verdict code stopped ("certifier", "conformance replay"); detail has the message.
  std::string internal_error;
};

// Passed to the conformance replay (lepp/audit/judge/conformance.h, ConformanceOptions).
struct CheckOptions {
  double angle_tolerance_deg = 1e-3;  // a triangle this close above theta may count as bad or good
  double point_tolerance_ulps = 8;    // how far a point may be from the exact choice, DBL_EPSILON x |coordinate| units
  bool area_centroid = false;         // the declared reading: the quad centroid is its area centroid (--centroid area)
  bool arithmetic_double = false;     // the declared reading of the arithmetic (--arithmetic double): inexact-* steps are notes
  // The certificate's precision-limit search: at most this many Lepp states per triangle
  // (certify::Options::tie_search_states; 0: no bound). lepp's built-in engines run
  // with the same bound (lepp/engines/builtin_engines.h).
  std::size_t tie_search_states = kTieSearchStates;
};

struct CaseResult {
  std::array<RowResult, kRows> rows;
  std::int64_t steiner_points = -1;  // points added (Ok runs)
  std::size_t exempt_triangles = 0;  // below theta but exempt by the small-input-angle rule
  std::size_t precision_exempt_triangles = 0;  // below theta but exempt by the precision limit
  RowResult& operator[](Row r) { return rows[static_cast<std::size_t>(r)]; }
  const RowResult& operator[](Row r) const { return rows[static_cast<std::size_t>(r)]; }
};

// The band where the paper claims termination: centroid theta <= 30 (Remark 15),
// midpoint theta <= alpha_limit, about 22 degrees (Theorem 9). check_run also asks
// that the input have no angle below 60 degrees (the class those results cover).
bool termination_claimed(Method method, double theta);

// Decides every row for one run. Never throws: an exception inside the
// certifier or the replay makes the rows it was deciding InternalError.
CaseResult check_run(const Pslg& validated, const EngineRequest& request, const EngineRun& run, const CheckOptions& options);


}  // namespace lepp::audit
