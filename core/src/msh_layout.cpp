// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind msh_layout.h: how a mesh maps onto Gmsh's model, for both .msh versions.
#include "msh_layout.h"

#include <algorithm>
#include <limits>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

#include "block_file.h"

namespace lepp::detail {
namespace {

// Groups items 0..count-1 by key (a counting sort over the distinct keys, in
// increasing order), filling `order` and one entity per key.
template <class Key, class Extend>
std::vector<MshEntity> group(std::size_t count, Key key, Extend extend, std::vector<int>& order) {
  std::map<int, std::size_t> sizes;
  for (std::size_t i = 0; i < count; ++i) ++sizes[key(i)];
  std::vector<MshEntity> entities;
  std::map<int, std::size_t> next;
  std::size_t at = 0;
  for (const auto& [tag, size] : sizes) {
    MshEntity e;
    e.tag = tag;
    e.begin = at;
    e.end = at + size;
    const double inf = std::numeric_limits<double>::infinity();
    e.box = {inf, inf, 0, -inf, -inf, 0};
    next[tag] = entities.size();
    entities.push_back(e);
    at += size;
  }
  std::vector<std::size_t> fill;
  for (const MshEntity& e : entities) fill.push_back(e.begin);
  order.assign(count, 0);
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t k = next[key(i)];
    order[fill[k]++] = static_cast<int>(i);
    extend(entities[k].box, i);
  }
  return entities;
}

}  // namespace

int MshLayout::physical_groups() const {
  int n = 0;
  for (const MshEntity& e : curves) n += e.physical != 0;
  for (const MshEntity& e : surfaces) n += e.physical != 0;
  return n;
}

MshLayout msh_layout(const Mesh& mesh, const MeshLabels& labels) {
  const std::size_t m = mesh.triangles.size(), l = mesh.constrained_edges.size();
  if (!labels.triangle_regions.empty() && labels.triangle_regions.size() != m)
    throw std::invalid_argument("msh writer: one region per triangle expected");
  if (!labels.edge_markers.empty() && labels.edge_markers.size() != l)
    throw std::invalid_argument("msh writer: one marker per constrained edge expected");
  MshLayout layout;
  layout.triangles = m;
  layout.lines = l;

  auto extend_with = [&](std::array<double, 6>& box, int v) {
    const Point& p = mesh.vertices[static_cast<std::size_t>(v)];
    box[0] = std::min(box[0], p.x);
    box[1] = std::min(box[1], p.y);
    box[3] = std::max(box[3], p.x);
    box[4] = std::max(box[4], p.y);
  };

  // Surfaces: region k + 1 is tag k + 1; the triangles no region reaches
  // ("domain") come after every region of the input.
  int regions = labels.region_count;
  for (int r : labels.triangle_regions) regions = std::max(regions, r);
  const int domain_tag = regions + 1;
  auto surface_of = [&](std::size_t t) {
    const int r = labels.triangle_regions.empty() ? 0 : labels.triangle_regions[t];
    return r > 0 ? r : domain_tag;
  };
  layout.surfaces = group(
      m, surface_of,
      [&](std::array<double, 6>& box, std::size_t t) {
        for (int v : mesh.triangles[t]) extend_with(box, v);
      },
      layout.triangle_order);
  for (MshEntity& e : layout.surfaces) {
    e.physical = e.tag;
    e.name = e.tag == domain_tag ? "domain" : fmt::format("region_{}", e.tag);
  }

  // Curves: marker k >= 1 is tag k, in the physical group "marker_k"; the edges
  // with marker 0 (none) or below (Gmsh's tags are positive) share one curve
  // after them, "unmarked". Every element is in a group: Gmsh keeps only those
  // when it saves, and meshio reads physical tags per block.
  int top = 0;
  for (int k : labels.edge_markers) top = std::max(top, k);
  const int unmarked_tag = top + 1;
  auto curve_of = [&](std::size_t e) {
    const int k = labels.edge_markers.empty() ? 0 : labels.edge_markers[e];
    return k >= 1 ? k : unmarked_tag;
  };
  layout.curves = group(
      l, curve_of,
      [&](std::array<double, 6>& box, std::size_t e) {
        extend_with(box, mesh.constrained_edges[e].a);
        extend_with(box, mesh.constrained_edges[e].b);
      },
      layout.line_order);
  for (MshEntity& e : layout.curves) {
    e.physical = e.tag;
    e.name = e.tag == unmarked_tag ? "unmarked" : fmt::format("marker_{}", e.tag);
  }
  return layout;
}

void write_physical_names(BlockFile& out, const MshLayout& layout) {
  out.print("$PhysicalNames\n{}\n", layout.physical_groups());
  for (const MshEntity& e : layout.curves)
    if (e.physical) out.print("1 {} \"{}\"\n", e.physical, e.name);
  for (const MshEntity& e : layout.surfaces)
    if (e.physical) out.print("2 {} \"{}\"\n", e.physical, e.name);
  out.print("$EndPhysicalNames\n");
}

}  // namespace lepp::detail
