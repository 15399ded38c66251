// SPDX-License-Identifier: GPL-3.0-or-later
// Simple exact checks of a refined mesh, for the reference engine's tests.
// Independent of the engine's code (the full certifier lives in
// properties/certify): rationals from GMP, every angle tested, not only the
// one the engine looks at. Each returns an empty string when the check holds,
// else what is wrong.
#pragma once
#include <string>

#include "lepp/mesh.h"
#include "lepp/pslg.h"

namespace lepp::reference::testing {

// Every angle below 90 degrees has sin^2 >= engine_sin2_threshold(theta)
// (exactly) unless the triangle is listed in `except` by its sorted ids.
std::string check_min_angle(const Mesh& mesh, double theta_deg, const std::vector<Tri>& except = {});
// The first input_vertices vertices are the input's, bit for bit, and each
// one that is an endpoint of a segment is a vertex of some triangle.
std::string check_input_vertices(const Mesh& mesh, const Pslg& input);
// Each input segment is a chain of constrained edges tagged with its id from
// one endpoint to the other, and no constrained edge is tagged otherwise.
std::string check_segment_chains(const Mesh& mesh, const Pslg& input);
// Every edge shared by two triangles and not constrained is locally Delaunay:
// the opposite vertex is not strictly inside the circumcircle (exact).
std::string check_locally_delaunay(const Mesh& mesh);
// Every triangle is counter-clockwise (exact orientation > 0).
std::string check_ccw(const Mesh& mesh);
// Every triangle has area <= max_area (exactly: |cross| <= 2 max_area).
std::string check_max_area(const Mesh& mesh, double max_area);

// Sign of the exact orientation of a, b, c: 1 left turn, -1 right turn, 0 collinear.
int orientation(const Point& a, const Point& b, const Point& c);
// Twice the area of the mesh, exactly, as a double (for comparisons with small integers).
double twice_area(const Mesh& mesh);

}  // namespace lepp::reference::testing
