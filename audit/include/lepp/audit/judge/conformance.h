// SPDX-License-Identifier: GPL-3.0-or-later
// Conformance: does a trace of Steiner points follow the paper's algorithm?
// Each point is replayed on the exact reference and must be the paper's
// choice (New Select Point with Remark 10 for centroid, Select Point with
// the constrained-edge rule for midpoint) for the Lepp of some bad triangle
// of the mesh at that moment. docs/AUDIT.md, "Conformance", says exactly what
// is accepted and why.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "lepp/mesh.h"
#include "lepp/pslg.h"
#include "lepp/refine.h"

namespace lepp::audit {

struct ConformanceOptions {
  Method method = Method::Centroid;
  double min_angle_deg = 30;
  // A triangle whose smallest angle is within this many degrees above theta
  // may still count as bad (below theta it is bad anyway: conformance only asks
  // that each inserted point be allowed, not that every bad triangle be fixed).
  double angle_tolerance_deg = 1e-3;
  // In units of DBL_EPSILON times the largest |coordinate| of the vertices
  // that define the choice, per coordinate.
  double point_tolerance_ulps = 8;
  double max_area = 0;  // > 0: triangles larger than this are bad too
  // Triangles larger than their region's bound are bad too (the trace was made
  // with lepp refine --region-areas; RefineOptions::region_area_bounds).
  bool region_area_bounds = false;
  // Accept any constrained Delaunay mesh of the same points: any
  // triangulation of each exactly cocircular cell, where the replay's own mesh
  // has another (docs/CONFORMANCE.md, "Cocircular cells").
  bool follow_cocircular_flips = true;
  // Triangles the search of the cells' other triangulations may look at per point.
  std::size_t cocircular_search_budget = 200000;
  // The declared reading of "the centroid of the quad": false, the paper's
  // vertex average (A+B+C+D)/4 (Lemma 11); true, the area centroid.
  bool area_centroid = false;
  // At a failing step whose deviation is a whole rule set (area-centroid,
  // triangle-centroid, terminal-midpoint, centroid-not-midpoint,
  // remark10-ignored, remark10-reversed, other-second-longest), the replay
  // continues with that rule allowed wherever it applies and names the next
  // deviation, until the trace ends (every deviation of the program in one
  // check: ConformanceFailure::chain) or a step fits no rule it can continue
  // with. One name that takes the trace to its end is one consistent variant.
  bool check_variant = true;
  // Theorem 2 on the terminal pair of every replayed step.
  bool theorem2_every_step = true;
  // The declared reading of the arithmetic (--arithmetic double): a step that is
  // the paper's choice once near ties of lengths count as ties (inexact-length),
  // or once triangles within double rounding above theta count as bad
  // (inexact-threshold, seen only with angle_tolerance_deg below about 1e-12),
  // is accepted, counted in ConformanceReport::inexact_steps; false (exact, the
  // default): such a step fails, named so.
  bool arithmetic_double = false;
};

// One choice the paper allows, as reported for a failing step.
struct ConformanceCandidate {
  Tri bad{{-1, -1, -1}};          // the bad triangle whose Lepp leads here
  std::vector<Tri> lepp;          // bad first, terminal triangle(s) last
  std::array<int, 2> terminal_edge{{-1, -1}};
  Rule rule = Rule::QuadCentroid;
  Point point;                    // the exact choice, rounded
  double distance = 0;            // max(|dx|, |dy|) to the trace's point
  double tolerance = 0;           // the point tolerance for this choice (same units as distance)
  double euclidean = 0;           // the Euclidean distance to the trace's point, for reports
  Tri t1{{-1, -1, -1}}, t2{{-1, -1, -1}};  // the terminal pair (t2 -1s: constrained terminal edge)
  std::array<int, 2> split_edge{{-1, -1}};  // a midpoint's edge
};

// One deviation of a trace (ConformanceFailure::chain).
struct DeviationLink {
  std::string deviation;       // the catalogue's name
  std::size_t first_step = 0;  // the first step that is its point, 1-based as the reports number steps
  std::size_t steps = 0;       // steps the continued replay took as its point (0: it could not continue with it)
};

struct ConformanceFailure {
  std::size_t step = 0;           // 0-based index in the trace
  Point point;                    // the trace's point
  std::string reason;             // one line
  std::vector<ConformanceCandidate> candidates;  // nearest first, capped
  std::size_t candidates_total = 0;              // before the cap
  double nearest_distance = -1;   // -1: the mesh had no bad triangle
  Mesh mesh;                      // the mesh just before the step (vertex ids as in the replay)
  // The named deviation that explains the point (docs/CONFORMANCE.md,
  // "Deviations"): "area-centroid", "remark10-reversed", ..., "unknown". Part of
  // the JSON contract, and of a conformance failure's shrink signature.
  std::string deviation = "unknown";
  std::string deviation_what;     // one line: which point of which configuration it is
  std::string deviation_definition;  // the catalogue's definition of the name
  // Where the deviation matched (its bad triangle, Lepp, terminal pair, the
  // rule's point) and the paper's choices at that configuration; none for unknown.
  std::optional<ConformanceCandidate> deviation_at;
  std::vector<ConformanceCandidate> deviation_paper;
  // check_variant: every step of the trace is the paper's choice or this
  // deviation's, and variant_steps of them are the deviation's.
  bool consistent_variant = false;
  std::size_t variant_steps = 0;
  // check_variant: every deviation of the trace, in the order the trace shows
  // them; chain[0] is `deviation` (a step's remark10-ignored becomes
  // remark10-reversed when a later step is only the reversed rule's point).
  std::vector<DeviationLink> chain;
  bool chain_complete = false;  // the replay reached the trace's end with the chain's variants allowed
  std::string chain_end;        // else where and why it stopped after the first step, one line ("": it did not go on)
  // Why it stopped, as a name (docs/CONFORMANCE.md, "The program's mesh"): "" (complete,
  // or it did not go on), "no-rule" (an unknown step on the exact mesh),
  // "program-mesh-lost" (a step no rule fits on the program's mesh as rebuilt),
  // "point-rule" (a point of one bad triangle, like circumcenter), "unreachable"
  // (a name already allowed, at a configuration the replay cannot reach with it),
  // "not-insertable" (the point cannot be inserted in the replay's mesh).
  std::string chain_end_reason;
  std::size_t chain_end_step = 0;  // the step it stopped at, 1-based (0: complete, or it did not go on)
  // The mesh the chain was followed on after the first step (MeshReading's names):
  // "" the exact one; "no-flips", "no-flips-but-splits", "double-incircle",
  // "float-points", "ties-kept" the program's, chosen by the arithmetic name of the
  // mesh, or tried where the exact chain lost a step (lepp/audit/judge/program_mesh.h).
  std::string mesh_reading;
  // mesh_reading was tried where the exact chain lost a step no rule fits (the
  // final mesh named no arithmetic), not read from the name of the final mesh.
  bool mesh_reading_fallback = false;
  // The mesh the step's picture and table of choices (mesh, candidates) are of: ""
  // the exact one; mesh_reading's name where the fallback's chain starts at the
  // failing step, so that they show the choices its deviation speaks of.
  std::string step_mesh_reading;
  // Steps that took the quad centroid inside the other triangle where one
  // second-longest edge is constrained: the paper's Remark 10, which a
  // reversed program never does (the evidence for remark10-ignored).
  std::size_t remark10_centroid_inside_steps = 0;
};

// Theorem 2 failing on the terminal pair of a replayed step.
struct Theorem2StepFailure {
  std::size_t step = 0;                       // 0-based index in the trace
  Point point;                                // the trace's point at that step
  std::array<int, 2> terminal_edge{{-1, -1}};
  Tri t1{{-1, -1, -1}}, t2{{-1, -1, -1}};
  int apex = -1;                              // the vertex whose angle is over 120 degrees
  double angle_deg = 0;                       // about
  Mesh mesh;                                  // the mesh just before the step
};

struct ConformanceReport {
  bool conforms = true;
  std::size_t steps = 0;          // points in the trace
  std::size_t steps_checked = 0;  // points found to be a choice (all of them when conforms)
  std::int64_t cocircular_ties = 0;   // the initial CDT's cocircular edges and the cocircular quads the insertions met
  std::int64_t cocircular_flips = 0;  // cocircular edges flipped to follow the implementation
  bool cocircular_search_exhausted = false;  // the failing step's search of the cells ran out of budget
  std::optional<ConformanceFailure> failure;
  std::optional<Theorem2StepFailure> theorem2_failure;  // the first step whose terminal pair breaks Theorem 2
  std::size_t theorem2_pairs_checked = 0;               // unconstrained terminal pairs of the replayed steps
  bool area_centroid = false;                           // the reading checked against
  bool arithmetic_double = false;                       // the arithmetic reading checked against
  // arithmetic_double: the steps accepted only under it, by name ("inexact-length", "inexact-threshold").
  std::map<std::string, std::size_t> inexact_steps;
  double seconds = 0;
};

// validated: the input after lepp::validate (throws std::invalid_argument
// otherwise). Only the trace's coordinates are compared: how the
// implementation numbers its vertices does not matter.
ConformanceReport check_conformance(const Pslg& validated, const std::vector<Point>& trace,
                                    const ConformanceOptions& options);

// "area-centroid from step 1; then remark10-reversed from step 41"
std::string chain_text(const std::vector<DeviationLink>& chain);
// A remark10-ignored in the failure's chain: which evidence of the trace names
// it, or that remark10-reversed fits as well (docs/CONFORMANCE.md). "" otherwise.
std::string remark10_ignored_note(const ConformanceFailure& failure);

// A few lines for a person: conforms, or the failing step with its nearest candidates.
std::string describe(const ConformanceReport& report, std::size_t max_candidates = 5);

}  // namespace lepp::audit
