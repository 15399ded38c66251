// SPDX-License-Identifier: GPL-3.0-or-later
// After an arithmetic name of the mesh (missing-flips, inexact-incircle,
// single-precision), the exact replay's mesh is not the program's, and its later
// steps cannot be matched there. The chain is followed again on the program's
// mesh as the replay rebuilds it (docs/CONFORMANCE.md, "The program's mesh").
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "lepp/audit/judge/conformance.h"
#include "lepp/audit/replay.h"

namespace lepp::audit {

// The name of a program that did not flip (always) after an insertion, and its
// definition (docs/CONFORMANCE.md, "Deviations").
constexpr const char* kMissingFlips = "missing-flips";
constexpr const char* kMissingFlipsDefinition =
    "the program did not flip (always) after an insertion: its final mesh is not constrained Delaunay, or a step is the "
    "paper's choice only on the mesh without flips; its intermediate meshes are not the replay's, and its steps after "
    "the first missing flip are judged on meshes it never had";

// The mesh a program named so had: missing-flips no flips, inexact-incircle flips
// decided in double, single-precision points at float rounding; Exact for any
// other name (the exact mesh is the program's as far as the output says).
MeshReading mesh_reading_for(const std::string& deviation);

// The trace replayed again from its first step on the mesh f.deviation names
// (mesh_reading_for), every step judged against the paper's choices and the
// catalogue there: f.chain becomes f.deviation at f.step, then every name the
// program's mesh shows, to the trace's end or to a named reason
// (chain_end_reason); f.mesh_reading says which mesh. When the name reads the
// exact mesh and the exact chain lost a step no rule fits (chain_end_reason
// "no-rule", the first failing step itself included), the meshes a program
// whose final mesh is Delaunay may still have had are tried (cocircular ties
// kept as inserted, flips decided in double, no flips, no flips but after
// splits): the one that follows farthest is kept when it goes past that step,
// its chain named again from the first step, with the mesh's arithmetic name
// (inexact-incircle, missing-flips; none for ties kept) at the lost step.
// Nothing changes otherwise, nor when options.check_variant is off.
void follow_program_mesh(const Pslg& validated, const std::vector<Point>& trace, const ConformanceOptions& options,
                         ConformanceFailure& f);

// The step where f's chain stopped at no rule (chain_end_reason "no-rule" or
// "program-mesh-lost"), as a failure of its own for a picture: the trace replayed
// again on the mesh the chain was followed on, with the chain's rules allowed, to
// just before that step; the nearest choices and the catalogue's diagnosis there.
// Empty for any other end, or when that replay does not get there.
std::optional<ConformanceFailure> chain_end_failure(const Pslg& validated, const std::vector<Point>& trace,
                                                    const ConformanceOptions& options, const ConformanceFailure& f);

}  // namespace lepp::audit
