// SPDX-License-Identifier: GPL-3.0-or-later
// The peers as audit engines: Shewchuk's Triangle (the triangle-wasm build under
// node, tools/triangle) and CGAL's quality mesher (engines/others/cgal_mesher.h). Part of
// the lepp_peer_engines library (not in the find_package package: it needs the
// source tree for Triangle).
#pragma once
#include <cstdint>
#include <string>

#include "lepp/audit/engine.h"

namespace lepp::audit {

// Triangle with -pq{theta} and its own Steiner budget -S (a run that uses it up is
// RunStatus::Stopped). Throws UsageError when node or triangle-wasm is missing.
Engine triangle_engine(const std::string& source_root, std::int64_t budget = 20000);

// CGAL's refine_Delaunay_mesh_2 with B = sin^2(theta), stopped at the timeout or
// after `budget` Steiner points (RunStatus::TimedOut / Stopped). Always run in a
// child process (isolated_engine.h): killed at the timeout if its own check
// between refinement steps does not stop it, a crash is RunStatus::Crashed, and
// memory_mb applies. Midpoint and centroid mean nothing to it: the method is ignored.
Engine cgal_engine(std::int64_t budget = 300000);

}  // namespace lepp::audit
