// SPDX-License-Identifier: GPL-3.0-or-later
// SVG drawings of a mesh (`lepp render`, and the audit's pictures of a finding):
// triangles coloured by quality or smallest angle, constrained edges bold, bad
// triangles marked, given triangles, edges and points highlighted, and optionally
// only a window around them. Plain data in, one SVG document out.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "lepp/mesh.h"
#include "lepp/pslg.h"

namespace lepp::render {

enum class ColorBy {
  Quality,  // area quality q = (4/sqrt 3) area / longest^2, 1 = equilateral
  Angle,    // smallest angle / 60 degrees
};

// Things to draw over the mesh, in one colour: triangles (indices into
// Mesh::triangles) outlined and tinted, edges (mesh vertex ids) as thick lines,
// points as rings (any coordinates: a candidate Steiner point, a missing vertex).
struct Highlight {
  std::vector<int> triangles;
  std::vector<std::array<int, 2>> edges;
  std::vector<Point> points;
  std::string colour = "red";  // any SVG colour
  std::string label;           // shown in the legend line when not empty
};

// An axis-aligned window in mesh coordinates.
struct Window {
  double min_x = 0, min_y = 0, max_x = 0, max_y = 0;
};

struct RenderOptions {
  ColorBy color = ColorBy::Quality;
  bool highlight_bad = false;  // outline and ring every triangle with smallest angle below min_angle_deg
  double min_angle_deg = 30;   // below this a triangle is bad (counted in the summary line)
  double width = 1000;         // drawing width in pixels
  std::string title;           // put before the summary line under the drawing
  std::vector<Highlight> highlights;
  // Draw only this window (the triangles meeting it, clipped to it); nullopt: the whole mesh.
  std::optional<Window> window;
  // An outline for a mesh too large to draw triangle by triangle (the overview of a
  // certificate of 10^6 triangles): the mesh's boundary edges, the constrained edges and
  // the highlights only; no triangles, no bad-triangle marks. The summary still counts them all.
  bool outline_only = false;
};

// The window around some triangles and points with context: their bounding box
// grown by `context` times its larger side on every side (at least the side of the
// longest edge of the given triangles, so a single point or a needle still shows its
// neighbourhood). Throws std::invalid_argument when given nothing.
Window window_around(const Mesh& mesh, const std::vector<int>& triangles, const std::vector<Point>& points = {},
                     double context = 1.0);

// The SVG document. Throws std::invalid_argument if the mesh has no triangles or a
// highlighted id is out of range. Without highlights and window, the bytes are
// those `lepp render` has always written (paper/ checks them).
std::string render_svg(const Mesh& mesh, const RenderOptions& options = {});

}  // namespace lepp::render
