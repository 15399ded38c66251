// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind arrays.h: NumPy arrays <-> lepp's data model.
#include "arrays.h"

#include <stdexcept>
#include <string>

#include <pybind11/stl.h>

namespace lepp::python {

static_assert(sizeof(Point) == 2 * sizeof(double), "Point must be two packed doubles to be viewed as (n, 2)");
static_assert(sizeof(Tri) == 3 * sizeof(std::int32_t) && sizeof(int) == sizeof(std::int32_t),
              "Tri must be three packed int32 to be viewed as (m, 3)");

namespace {

using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Ints = py::array_t<std::int32_t, py::array::c_style | py::array::forcecast>;

bool present(const py::dict& d, const char* key) { return d.contains(key) && !d[key].is_none(); }

// A (rows, columns) array (a flat one when columns is 1); ValueError naming the key otherwise.
template <class Array>
Array table(const py::dict& d, const char* key, py::ssize_t columns) {
  Array a = d[key].cast<Array>();
  const bool flat = columns == 1 && a.ndim() == 1;
  if (!flat && (a.ndim() != 2 || a.shape(1) != columns))
    throw std::invalid_argument(std::string(key) + ": expected an array of shape (n, " + std::to_string(columns) + ")");
  return a;
}

}  // namespace

Pslg pslg_from_dict(const py::dict& d) {
  Pslg p;
  if (present(d, "source")) p.source = d["source"].cast<std::string>();
  if (present(d, "vertices")) {
    Doubles v = table<Doubles>(d, "vertices", 2);
    const double* x = v.data();
    p.vertices.resize(static_cast<std::size_t>(v.shape(0)));
    for (std::size_t i = 0; i < p.vertices.size(); ++i) p.vertices[i] = {x[2 * i], x[2 * i + 1]};
  }
  if (present(d, "vertex_markers")) {
    Ints m = table<Ints>(d, "vertex_markers", 1);
    p.vertex_markers.assign(m.data(), m.data() + m.size());
  }
  if (present(d, "segments")) {
    Ints s = table<Ints>(d, "segments", 2);
    const std::int32_t* ab = s.data();
    p.segments.resize(static_cast<std::size_t>(s.shape(0)));
    for (std::size_t i = 0; i < p.segments.size(); ++i) p.segments[i] = {ab[2 * i], ab[2 * i + 1], 0};
    if (present(d, "segment_markers")) {
      Ints m = table<Ints>(d, "segment_markers", 1);
      if (static_cast<std::size_t>(m.size()) != p.segments.size())
        throw std::invalid_argument("segment_markers: expected one per segment");
      for (std::size_t i = 0; i < p.segments.size(); ++i) p.segments[i].marker = m.data()[i];
    }
  }
  if (present(d, "holes")) {
    Doubles h = table<Doubles>(d, "holes", 2);
    for (py::ssize_t i = 0; i < h.shape(0); ++i) p.holes.push_back({h.at(i, 0), h.at(i, 1)});
  }
  if (present(d, "regions")) {
    Doubles r = table<Doubles>(d, "regions", 4);
    for (py::ssize_t i = 0; i < r.shape(0); ++i) p.regions.push_back({{r.at(i, 0), r.at(i, 1)}, r.at(i, 2), r.at(i, 3)});
  }
  // Where each item was read (a PSLG that came from a file), for messages naming the line.
  auto lines = [&](const char* key, std::vector<int>& out, std::size_t count) {
    if (!present(d, key)) return;
    Ints l = table<Ints>(d, key, 1);
    if (static_cast<std::size_t>(l.size()) == count) out.assign(l.data(), l.data() + l.size());
  };
  lines("vertex_lines", p.vertex_lines, p.vertices.size());
  lines("segment_lines", p.segment_lines, p.segments.size());
  lines("hole_lines", p.hole_lines, p.holes.size());
  lines("region_lines", p.region_lines, p.regions.size());
  return p;
}

py::dict pslg_to_dict(const Pslg& p) {
  py::dict d;
  d["vertices"] = take_points(std::vector<Point>(p.vertices));
  if (!p.vertex_markers.empty()) d["vertex_markers"] = int_array(p.vertex_markers);
  std::vector<int> ab, markers;
  for (const Segment& s : p.segments) ab.insert(ab.end(), {s.a, s.b}), markers.push_back(s.marker);
  d["segments"] = int_array(ab, 2);
  d["segment_markers"] = int_array(markers);
  d["holes"] = take_points(std::vector<Point>(p.holes));
  py::array_t<double> regions({static_cast<py::ssize_t>(p.regions.size()), py::ssize_t{4}});
  auto r = regions.mutable_unchecked<2>();
  for (std::size_t i = 0; i < p.regions.size(); ++i) {
    const auto k = static_cast<py::ssize_t>(i);
    r(k, 0) = p.regions[i].at.x, r(k, 1) = p.regions[i].at.y, r(k, 2) = p.regions[i].attribute, r(k, 3) = p.regions[i].max_area;
  }
  d["regions"] = regions;
  d["source"] = p.source;
  if (!p.vertex_lines.empty()) d["vertex_lines"] = int_array(p.vertex_lines);
  if (!p.segment_lines.empty()) d["segment_lines"] = int_array(p.segment_lines);
  if (!p.hole_lines.empty()) d["hole_lines"] = int_array(p.hole_lines);
  if (!p.region_lines.empty()) d["region_lines"] = int_array(p.region_lines);
  return d;
}

Mesh mesh_from_dict(const py::dict& d) {
  Mesh mesh;
  if (!present(d, "vertices") || !present(d, "triangles")) throw std::invalid_argument("a mesh needs vertices and triangles");
  Doubles v = table<Doubles>(d, "vertices", 2);
  const double* x = v.data();
  mesh.vertices.resize(static_cast<std::size_t>(v.shape(0)));
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) mesh.vertices[i] = {x[2 * i], x[2 * i + 1]};
  Ints t = table<Ints>(d, "triangles", 3);
  const std::int32_t* abc = t.data();
  mesh.triangles.resize(static_cast<std::size_t>(t.shape(0)));
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) mesh.triangles[i] = {abc[3 * i], abc[3 * i + 1], abc[3 * i + 2]};
  if (present(d, "edges")) {
    Ints e = table<Ints>(d, "edges", 2);
    std::vector<std::int32_t> ids(static_cast<std::size_t>(e.shape(0)), -1);
    if (present(d, "edge_segments")) {
      Ints s = table<Ints>(d, "edge_segments", 1);
      if (static_cast<std::size_t>(s.size()) != ids.size()) throw std::invalid_argument("edge_segments: expected one per edge");
      ids.assign(s.data(), s.data() + s.size());
    }
    for (std::size_t i = 0; i < ids.size(); ++i) mesh.constrained_edges.push_back({e.data()[2 * i], e.data()[2 * i + 1], ids[i]});
  }
  if (present(d, "input_vertices")) {
    const auto n = d["input_vertices"].cast<std::size_t>();
    if (n > mesh.vertices.size()) throw std::invalid_argument("input_vertices: more than the mesh's vertices");
    mesh.input_vertices = n;
  }
  return mesh;
}

MeshLabels labels_from_dict(const py::dict& d, const Mesh& mesh) {
  // An empty array is none of that kind (mesh_labels() gives none for an input without regions).
  MeshLabels labels;
  if (present(d, "edge_markers")) {
    Ints m = table<Ints>(d, "edge_markers", 1);
    if (m.size() != 0 && static_cast<std::size_t>(m.size()) != mesh.constrained_edges.size())
      throw std::invalid_argument("edge_markers: expected one per edge");
    labels.edge_markers.assign(m.data(), m.data() + m.size());
  }
  if (present(d, "triangle_regions")) {
    Ints r = table<Ints>(d, "triangle_regions", 1);
    if (r.size() != 0 && static_cast<std::size_t>(r.size()) != mesh.triangles.size())
      throw std::invalid_argument("triangle_regions: expected one per triangle");
    labels.triangle_regions.assign(r.data(), r.data() + r.size());
  }
  if (present(d, "region_count")) labels.region_count = d["region_count"].cast<int>();
  return labels;
}

py::dict unimprovable_to_dict(const UnimprovableTriangle& u) {
  py::dict d;
  d["triangle"] = py::make_tuple(u.triangle[0], u.triangle[1], u.triangle[2]);
  d["apex"] = u.apex;
  d["segment1"] = u.segment1;
  d["segment2"] = u.segment2;
  d["input_angle"] = u.input_angle_deg;
  d["reason"] = to_string(u.reason);  // small-input-angle or double-precision (ALGORITHM.md 8, 8b)
  return d;
}

std::vector<UnimprovableTriangle> unimprovable_from_list(const py::list& list) {
  std::vector<UnimprovableTriangle> out;
  for (const py::handle item : list) {
    const py::dict d = item.cast<py::dict>();
    UnimprovableTriangle u;
    const auto t = d["triangle"].cast<std::vector<int>>();
    if (t.size() != 3) throw std::invalid_argument("unimprovable: a triangle is three vertex ids");
    u.triangle = {t[0], t[1], t[2]};
    u.apex = d["apex"].cast<int>();
    u.segment1 = d["segment1"].cast<int>();
    u.segment2 = d["segment2"].cast<int>();
    if (d.contains("input_angle")) u.input_angle_deg = d["input_angle"].cast<double>();
    if (d.contains("reason")) {
      const auto reason = d["reason"].cast<std::string>();
      if (reason == to_string(LeftReason::DoublePrecision)) u.reason = LeftReason::DoublePrecision;
      else if (reason != to_string(LeftReason::SmallInputAngle))
        throw std::invalid_argument("unimprovable: reason is small-input-angle or double-precision, not " + reason);
    }
    out.push_back(u);
  }
  return out;
}

py::array_t<double> take_points(std::vector<Point>&& points) {
  if (points.empty()) return py::array_t<double>(std::vector<py::ssize_t>{0, 2});
  auto* owned = new std::vector<Point>(std::move(points));
  py::capsule base(owned, [](void* p) { delete static_cast<std::vector<Point>*>(p); });
  return py::array_t<double>({static_cast<py::ssize_t>(owned->size()), py::ssize_t{2}},
                             reinterpret_cast<const double*>(owned->data()), base);
}

py::array_t<std::int32_t> take_triangles(std::vector<Tri>&& triangles) {
  if (triangles.empty()) return py::array_t<std::int32_t>(std::vector<py::ssize_t>{0, 3});
  auto* owned = new std::vector<Tri>(std::move(triangles));
  py::capsule base(owned, [](void* p) { delete static_cast<std::vector<Tri>*>(p); });
  return py::array_t<std::int32_t>({static_cast<py::ssize_t>(owned->size()), py::ssize_t{3}},
                                   reinterpret_cast<const std::int32_t*>(owned->data()), base);
}

py::array_t<std::int32_t> int_array(const std::vector<int>& values, std::size_t columns) {
  const auto rows = static_cast<py::ssize_t>(values.size() / columns);
  if (columns == 1) return py::array_t<std::int32_t>(rows, values.data());
  return py::array_t<std::int32_t>({rows, static_cast<py::ssize_t>(columns)}, values.data());
}

}  // namespace lepp::python
