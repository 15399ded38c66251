// SPDX-License-Identifier: GPL-3.0-or-later
// One finding on disk, self-contained: DIR/input.poly (the shrunk input),
// DIR/out.* (what the engine wrote, or its mesh and trace for an in-process
// engine), DIR/finding.svg (the mesh with the violation marked in red),
// DIR/finding.md (the row, its paper passage, the verdict line) and
// DIR/reproduce.sh (one command line that reproduces it).
#pragma once
#include <string>

#include "lepp/audit/checks.h"
#include "lepp/audit/engine.h"

namespace lepp::audit {

struct FindingText {
  std::string engine, input_origin, reproduce;
  double theta = 0;
  Method method = Method::Centroid;
};

void save_finding(const std::string& dir, Row row, const Pslg& input, const EngineRun& run, const RowResult& result,
                  const FindingText& text);

// The SVG: triangles light, constrained edges bold, the violation's triangles,
// edges and vertices red. Without a mesh, the input alone.
std::string finding_svg(const Pslg& input, const Mesh* mesh, const RowResult& result, const std::string& title);

}  // namespace lepp::audit
