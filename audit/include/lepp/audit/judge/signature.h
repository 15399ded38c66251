// SPDX-License-Identifier: GPL-3.0-or-later
// What makes two failures of a row the same bug, so that shrinking keeps it
// (issue 19: a failure of the paper's Rectangle162, inside every claim, once
// shrank to a sliver at a tiny input angle, a different failure). A shrink
// candidate counts only when it fails the same row with the same signature:
//   certificate  how the run ended when it left no mesh (crashed by signal N, by
//                an exception, exit status N, unreadable output), else the kind
//                (lepp::certify::Reason) of the row's first violation;
//   min-angle    the kind of the first violation, and the input's class: a
//                failure on an input with no angle below 60 degrees (inside
//                every claim) keeps only candidates in that class;
//   theorem-2    the kind of the first violation;
//   termination  the verdict (failed: inside the claimed class; a finding:
//                outside it) and how the run ended (timed out, stopped);
//   conformance  the named deviation of the first non-conforming step.
// An internal error of the audit (Verdict::InternalError, on any row): the
// stage of the verdict code that stopped ("certifier", "conformance replay").
#pragma once
#include <string>

#include "lepp/audit/judge/checks.h"
#include "lepp/audit/engine.h"

namespace lepp::audit {

struct FailureSignature {
  Verdict verdict = Verdict::Failed;
  std::string kind;          // as above; "" when the row gives nothing finer
  bool well_shaped = false;  // min-angle: the input has no angle below 60 degrees

  std::string text() const;  // "not-locally-delaunay", "angle-below-theta (input angles >= 60)", ...
};

FailureSignature failure_signature(Row row, const Pslg& input, const EngineRun& run, const RowResult& result);

// Does a candidate's failure keep the original's? Same verdict and kind; an
// original inside the well-shaped class keeps only candidates inside it.
bool keeps(const FailureSignature& original, const FailureSignature& candidate);

// The named deviation of a conformance failure (docs/CONFORMANCE.md), the
// conformance row's kind. Empty when the row has none.
std::string conformance_deviation(const RowResult& result);

}  // namespace lepp::audit
