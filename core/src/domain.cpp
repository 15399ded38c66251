// SPDX-License-Identifier: GPL-3.0-or-later
// The domain options of lepp/input.h: a point set's convex hull (Triangle
// without -p), the hull's segments added to any PSLG (Triangle's -c), and
// crossing segments split at their rounded exact intersection.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_plus_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <fmt/format.h>

#include "lepp/input.h"
#include "lepp/io.h"
#include "lepp/validate.h"
#include "validate_geometry.h"

namespace lepp {
namespace {

std::uint64_t pair_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

struct PointHash {
  std::size_t operator()(const Point& p) const {
    return std::hash<double>()(p.x) * 0x9E3779B97F4A7C15ull ^ std::hash<double>()(p.y);
  }
};

// The double nearest to an exact number (ties to even), whatever rounding
// CGAL::to_double uses: its neighbours are compared exactly.
template <class ET>
double nearest_double(const ET& x) {
  const double d = CGAL::to_double(x);
  double best = d;
  ET best_gap = CGAL::abs(x - ET(d));
  for (double c : {std::nextafter(d, -HUGE_VAL), std::nextafter(d, HUGE_VAL)}) {
    if (!std::isfinite(c)) continue;
    const ET gap = CGAL::abs(x - ET(c));
    if (gap < best_gap) {
      best = c;
      best_gap = gap;
    } else if (gap == best_gap) {  // a tie: the even significand
      std::int64_t bc = 0, bb = 0;
      std::memcpy(&bc, &c, sizeof c);
      std::memcpy(&bb, &best, sizeof best);
      if ((bc & 1) == 0 && (bb & 1) != 0) best = c;
    }
  }
  return best;
}

}  // namespace

std::vector<Segment> convex_hull_segments(const Pslg& pslg) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const std::vector<Point>& v = pslg.vertices;
  std::vector<int> order;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (std::isfinite(v[i].x) && std::isfinite(v[i].y)) order.push_back(static_cast<int>(i));
  std::stable_sort(order.begin(), order.end(), [&](int i, int j) {
    const Point &p = v[static_cast<std::size_t>(i)], &q = v[static_cast<std::size_t>(j)];
    return p.x < q.x || (p.x == q.x && p.y < q.y);
  });
  // One id per distinct point: the first in file order (stable sort).
  order.erase(std::unique(order.begin(), order.end(),
                          [&](int i, int j) { return v[static_cast<std::size_t>(i)] == v[static_cast<std::size_t>(j)]; }),
              order.end());
  if (order.size() < 3) return {};
  auto turn = [&](int a, int b, int c) {
    auto P = [&](int i) { return K::Point_2(v[static_cast<std::size_t>(i)].x, v[static_cast<std::size_t>(i)].y); };
    return CGAL::orientation(P(a), P(b), P(c));
  };
  // Andrew's monotone chain, popping only at right turns so that vertices on
  // the hull's edges stay on it (they would be split there anyway).
  std::vector<int> hull;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t base = hull.size();
    for (std::size_t k = 0; k < order.size(); ++k) {
      const int p = pass == 0 ? order[k] : order[order.size() - 1 - k];
      while (hull.size() >= base + 2 && turn(hull[hull.size() - 2], hull.back(), p) == CGAL::RIGHT_TURN) hull.pop_back();
      hull.push_back(p);
    }
    hull.pop_back();  // the last point starts the other chain
  }
  bool flat = true;
  for (std::size_t k = 0; k + 2 < order.size() && flat; ++k) flat = turn(order[0], order[k + 1], order[k + 2]) == CGAL::COLLINEAR;
  if (flat) return {};  // all collinear: no hull (validate() says so)
  std::unordered_set<std::uint64_t> existing;
  for (const Segment& s : pslg.segments) existing.insert(pair_key(s.a, s.b));
  std::vector<Segment> out;
  for (std::size_t k = 0; k < hull.size(); ++k) {
    const int a = hull[k], b = hull[(k + 1) % hull.size()];
    if (a != b && !existing.count(pair_key(a, b))) out.push_back({a, b, 1});
  }
  return out;
}

std::size_t split_crossings(Pslg& pslg, std::vector<std::string>& warnings) {
  using EK = CGAL::Exact_predicates_exact_constructions_kernel;
  using Vb = CGAL::Triangulation_vertex_base_2<EK>;
  using Fb = CGAL::Constrained_triangulation_face_base_2<EK>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
  using Cdt = CGAL::Constrained_Delaunay_triangulation_2<EK, Tds, CGAL::Exact_intersections_tag>;
  using Cdtp = CGAL::Constrained_triangulation_plus_2<Cdt>;
  using Vh = Cdtp::Vertex_handle;

  detail::WarningSink sink(warnings, "crossing split");
  std::unordered_map<Point, int, PointHash> id_of;
  for (std::size_t i = 0; i < pslg.vertices.size(); ++i) id_of.emplace(pslg.vertices[i], static_cast<int>(i));
  const std::size_t before = pslg.vertices.size();
  if (pslg.segment_origin.size() != pslg.segments.size()) {
    pslg.segment_origin.resize(pslg.segments.size());
    std::iota(pslg.segment_origin.begin(), pslg.segment_origin.end(), 0);
  }
  // Rounding moves a crossing point off its segments by up to half an ulp, so
  // the pieces may cross again near it: a few rounds settle it.
  for (int round = 0; round < 4; ++round) {
    Cdtp cdt;
    std::vector<Vh> handle(pslg.vertices.size());
    std::map<Vh, int> input_id;
    for (std::size_t i = 0; i < pslg.vertices.size(); ++i) {
      handle[i] = cdt.insert(EK::Point_2(pslg.vertices[i].x, pslg.vertices[i].y));
      input_id.emplace(handle[i], static_cast<int>(i));
    }
    std::vector<Cdtp::Constraint_id> ids;
    for (const Segment& s : pslg.segments)
      ids.push_back(cdt.insert_constraint(handle[static_cast<std::size_t>(s.a)], handle[static_cast<std::size_t>(s.b)]));
    std::map<Vh, int> new_id;
    std::vector<Segment> pieces;
    std::vector<int> lines, origin;
    bool changed = false;
    for (std::size_t s = 0; s < pslg.segments.size(); ++s) {
      std::vector<Vh> along(cdt.vertices_in_constraint_begin(ids[s]), cdt.vertices_in_constraint_end(ids[s]));
      if (!along.empty() && along.front() != handle[static_cast<std::size_t>(pslg.segments[s].a)])
        std::reverse(along.begin(), along.end());
      std::vector<int> chain;
      for (Vh vh : along) {
        if (auto it = input_id.find(vh); it != input_id.end()) {
          if (vh == along.front() || vh == along.back()) chain.push_back(it->second);
          continue;  // an input vertex on the segment: validate() splits there
        }
        auto [it, fresh] = new_id.emplace(vh, -1);
        if (fresh) {
          const Point p{nearest_double(CGAL::exact(vh->point().x())), nearest_double(CGAL::exact(vh->point().y()))};
          auto [at, added] = id_of.emplace(p, static_cast<int>(pslg.vertices.size()));
          if (added) {
            pslg.vertices.push_back(p);
            pslg.vertex_lines.push_back(0);
            if (!pslg.vertex_markers.empty()) pslg.vertex_markers.push_back(pslg.segments[s].marker);
          }
          it->second = at->second;
          changed = true;
        }
        if (chain.empty() || chain.back() != it->second) chain.push_back(it->second);
      }
      const int line = s < pslg.segment_lines.size() ? pslg.segment_lines[s] : 0;
      if (chain.size() > 2)
        sink.add(fmt::format("{}: segment {} crosses other segments; split at {} point{} (first ({}, {})), "
                             "--split-crossings",
                             detail::where(pslg.source, line), pslg.segment_origin[s] + 1, chain.size() - 2,
                             chain.size() == 3 ? "" : "s", pslg.vertices[static_cast<std::size_t>(chain[1])].x,
                             pslg.vertices[static_cast<std::size_t>(chain[1])].y));
      for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
        if (chain[k] == chain[k + 1]) continue;
        pieces.push_back({chain[k], chain[k + 1], pslg.segments[s].marker});
        lines.push_back(line);
        origin.push_back(pslg.segment_origin[s]);
      }
    }
    pslg.segments = std::move(pieces);
    pslg.segment_lines = std::move(lines);
    pslg.segment_origin = std::move(origin);
    if (!changed) break;
  }
  pslg.crossing_vertices += pslg.vertices.size() - before;
  return pslg.vertices.size() - before;
}

Pslg validate(const Pslg& input, const DomainOptions& options, std::vector<std::string>& warnings) {
  if (!options.convex_hull && !options.split_crossings && !input.segments.empty()) return validate(input, warnings);
  Pslg p = input;
  if (options.convex_hull || p.segments.empty()) {
    std::vector<Segment> hull = convex_hull_segments(p);
    p.segments.insert(p.segments.end(), hull.begin(), hull.end());
    p.segment_lines.resize(p.segments.size(), 0);
  }
  return detail::validate(p, options.split_crossings, warnings);
}

}  // namespace lepp
