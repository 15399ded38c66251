// SPDX-License-Identifier: GPL-3.0-or-later
// The diagnosis of a step finding (a conformance failure, Theorem 2 failing
// at a replayed step), for the reader of a finding: the mesh just before the
// step drawn around the point (bad triangles, the Lepp and terminal pair of
// the nearest choice, every choice marked with its rule, the program's point,
// the named deviation's point) and the words (the deviation, its definition,
// Euclidean distances, whether one consistent variant explains every step,
// whether the final mesh says the intermediate meshes differ).
#pragma once
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "lepp/audit/conformance.h"
#include "lepp/mesh.h"

namespace lepp::audit {

struct StepDiagnosis {
  bool theorem2 = false;           // false: a conformance failure; true: Theorem 2 at a step
  std::size_t step = 0;            // 1-based
  std::size_t steps = 0;           // in the trace
  Point point;                     // the program's point at that step
  Mesh mesh;                       // the replay's mesh just before the step
  double theta = 30;
  bool area_centroid = false;      // the declared reading
  std::string reason;              // conformance: why the point is no choice
  // Conformance: the nearest of the paper's choices (candidates_total in all),
  // the named deviation and where it matched, the paper's choices there.
  std::vector<ConformanceCandidate> candidates;
  std::size_t candidates_total = 0;
  std::string deviation, deviation_what, deviation_definition;
  std::optional<ConformanceCandidate> deviation_at;
  std::vector<ConformanceCandidate> deviation_paper;
  bool consistent_variant = false;
  std::size_t variant_steps = 0;
  // The final mesh fails the certifier's Delaunay check: the program's
  // intermediate meshes probably differ from the replay's.
  bool final_not_delaunay = false;
  // Theorem 2: the terminal pair and the apex over 120 degrees.
  std::array<int, 2> terminal_edge{{-1, -1}};
  Tri t1{{-1, -1, -1}}, t2{{-1, -1, -1}};
  int apex = -1;
  double angle_deg = 0;
};

StepDiagnosis conformance_diagnosis(const ConformanceReport& report, double theta, bool final_not_delaunay);
StepDiagnosis theorem2_diagnosis(const ConformanceReport& report, double theta);

// A markdown section ("## The step"), for finding.md.
std::string diagnosis_markdown(const StepDiagnosis& d);
// lepp::render's drawing of the mesh before the step, cropped around the
// point. Throws std::invalid_argument when the mesh cannot be drawn.
std::string diagnosis_svg(const StepDiagnosis& d, const std::string& title);

}  // namespace lepp::audit
