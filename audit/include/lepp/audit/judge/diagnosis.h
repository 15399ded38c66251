// SPDX-License-Identifier: GPL-3.0-or-later
// The diagnosis of a step finding (a conformance failure, Theorem 2 failing
// at a replayed step), for the reader of a finding: the mesh just before the
// step drawn around the point (bad triangles, the Lepp and terminal pair of
// the nearest choice, every choice marked with its rule, the program's point,
// the named deviation's point) and the words (the deviation, its definition,
// Euclidean distances, whether one consistent variant explains every step,
// whether the final mesh says the intermediate meshes differ).
#pragma once
#include <cstddef>
#include <memory>
#include <string>
#include <variant>

#include "lepp/audit/judge/conformance.h"
#include "lepp/mesh.h"

namespace lepp::audit {

struct StepDiagnosis {
  // The failing step as the conformance report has it: a conformance failure
  // (the nearest of the paper's choices, the named deviation and where it
  // matched, the paper's choices there, the consistent variant), or Theorem 2
  // failing on the terminal pair of a replayed step (the pair, the apex over
  // 120 degrees). Each holds the replay's mesh just before the step.
  std::variant<ConformanceFailure, Theorem2StepFailure> failure;
  std::size_t steps = 0;           // in the trace
  double theta = 30;
  bool area_centroid = false;      // the declared reading
  // The final mesh fails the certifier's Delaunay check: the program's
  // intermediate meshes probably differ from the replay's.
  bool final_not_delaunay = false;
  // A conformance failure whose chain of deviations stopped at a step no rule
  // fits (chain_end_reason no-rule or program-mesh-lost): that step, on the mesh
  // the chain was followed on (chain-end.svg of the finding); null otherwise.
  std::shared_ptr<const StepDiagnosis> chain_end;

  std::size_t step() const;        // 1-based
  const Point& point() const;      // the program's point at that step
  const Mesh& mesh() const;        // the replay's mesh just before the step
};

StepDiagnosis conformance_diagnosis(const ConformanceReport& report, double theta, bool final_not_delaunay);
StepDiagnosis theorem2_diagnosis(const ConformanceReport& report, double theta);

// A markdown section ("## The step"), for finding.md.
std::string diagnosis_markdown(const StepDiagnosis& d);
// lepp::render's drawing of the mesh before the step, cropped around the
// point. Throws std::invalid_argument when the mesh cannot be drawn.
std::string diagnosis_svg(const StepDiagnosis& d, const std::string& title);

}  // namespace lepp::audit
