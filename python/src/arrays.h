// SPDX-License-Identifier: GPL-3.0-or-later
// NumPy arrays <-> lepp's data model. A PSLG comes in as a dict of arrays that
// lepp/_convert.py has already given their dtypes and shapes (vertices (n, 2)
// float64, segments (m, 2) int32, ...); a mesh goes out as arrays that own the
// engine's vectors (moved into a capsule: no copy).
#pragma once
#include <cstdint>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "lepp/mesh.h"
#include "lepp/mesh_labels.h"
#include "lepp/pslg.h"
#include "lepp/refine.h"

namespace lepp::python {

namespace py = pybind11;

// Keys: vertices, segments, segment_markers, vertex_markers, holes, regions
// ((r, 4): x, y, attribute, max_area), source (a name for messages) and, for a
// PSLG read from a file, vertex_lines, segment_lines, hole_lines, region_lines
// (where each item was read). Missing keys are empty. Only the GIL holder may call it.
Pslg pslg_from_dict(const py::dict& d);
// The same keys (0-based segment ids), with the arrays copied out of the Pslg.
py::dict pslg_to_dict(const Pslg& pslg);

// Keys: vertices (n, 2), triangles (m, 3), and optionally edges (k, 2) with
// edge_segments (k,) (constrained edges and their input segment ids, -1 unknown)
// and input_vertices (how many leading vertices are the input's, 0: unknown).
Mesh mesh_from_dict(const py::dict& d);

// The labels the VTU and Gmsh writers take (lepp/mesh_labels.h) from a mesh dict's
// edge_markers (one per edge), triangle_regions (one per triangle) and
// region_count; missing keys give no labels of that kind.
MeshLabels labels_from_dict(const py::dict& d, const Mesh& mesh);

// A triangle left bad by the small-input-angle rule as a dict (triangle, apex,
// segment1, segment2, input_angle) and back.
py::dict unimprovable_to_dict(const UnimprovableTriangle& u);
std::vector<UnimprovableTriangle> unimprovable_from_list(const py::list& list);

// (n, 2) float64 and (m, 3) int32 arrays that take the vectors over.
py::array_t<double> take_points(std::vector<Point>&& points);
py::array_t<std::int32_t> take_triangles(std::vector<Tri>&& triangles);
py::array_t<std::int32_t> int_array(const std::vector<int>& values, std::size_t columns = 1);

}  // namespace lepp::python
