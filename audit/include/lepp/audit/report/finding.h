// SPDX-License-Identifier: GPL-3.0-or-later
// One finding on disk, self-contained: DIR/input.poly (the shrunk input),
// DIR/out.* (what the engine wrote, or its mesh and trace for an in-process
// engine), DIR/finding.svg (lepp::render's drawing of the mesh with the
// violation marked in red; DIR/finding-zoom.svg, the window around it),
// DIR/finding.md (the row, its paper passage, the verdict line) and
// DIR/reproduce.sh (one command line that reproduces it).
#pragma once
#include <cstddef>
#include <string>

#include "lepp/audit/judge/checks.h"
#include "lepp/audit/engine.h"

namespace lepp::audit {

struct FindingText {
  std::string engine, input_origin, reproduce;
  double theta = 0;
  Method method = Method::Centroid;
  // How the saved input relates to the input as found: "shrunk from" only when it was.
  bool shrink_tried = true;           // false under --no-shrink
  std::size_t shrink_steps = 0;       // edits kept
  std::size_t original_vertices = 0, original_segments = 0, original_holes = 0;
  std::string original_detail;        // the row's line on the input as found
  std::string signature;              // what the shrinking kept (judge/signature.h)
  std::string nondeterminism;         // not empty: two runs on the same input differed (how)
};

void save_finding(const std::string& dir, Row row, const Pslg& input, const EngineRun& run, const RowResult& result,
                  const FindingText& text);

// The plain SVG used when there is no mesh to render (a crash, unreadable output)
// or the renderer refuses it: the input's segments, and the violation's marks in red.
std::string finding_svg(const Pslg& input, const Mesh* mesh, const RowResult& result, const std::string& title);

}  // namespace lepp::audit
