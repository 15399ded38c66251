// SPDX-License-Identifier: GPL-3.0-or-later
// The geometric checks of validate(), on a CGAL constrained triangulation
// with exact predicates (Epick): vertices on segments, overlaps,
// crossings, collinear input, hole points, the empty domain. O(n log n): the
// triangulation finds what pair loops would (a crossing throws; only then is
// the partner found by one scan).
#include "validate_geometry.h"

#include <algorithm>
#include <cstdint>
#include <deque>
#include <stdexcept>
#include <unordered_map>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <fmt/format.h>

#include "lepp/io.h"

namespace lepp::detail {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;  // exact predicates, all we use
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;  // the vertex id
using Fb = CGAL::Constrained_triangulation_face_base_2<K, CGAL::Triangulation_face_base_with_info_2<int, K>>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
// Segments may pass through vertices and overlap (no new point needed), but a
// proper crossing throws: that is exactly the line between repair and error.
// Delaunay: a constraint then crosses few edges (a plain triangulation of
// spatially sorted points has long fans that every constraint must cut).
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::No_constraint_intersection_requiring_constructions_tag>;
using Vh = Cdt::Vertex_handle;
using Fh = Cdt::Face_handle;

enum FaceState : int { kInDomain = 0, kOutside = 1, kInHole = 2 };

K::Point_2 to_cgal(const Point& p) { return {p.x, p.y}; }

int line_at(const std::vector<int>& lines, std::size_t i) { return i < lines.size() ? lines[i] : 0; }

std::string at_line(const std::vector<int>& lines, std::size_t i) {
  int line = line_at(lines, i);
  return line > 0 ? fmt::format(" (line {})", line) : std::string();
}

// Segment s crossed an earlier one: find which (exact orientations, one scan).
[[noreturn]] void report_crossing(const Pslg& pslg, std::size_t s) {
  auto pt = [&](int v) { return to_cgal(pslg.vertices[static_cast<std::size_t>(v)]); };
  const K::Point_2 a = pt(pslg.segments[s].a), b = pt(pslg.segments[s].b);
  for (std::size_t j = 0; j < s; ++j) {
    const K::Point_2 c = pt(pslg.segments[j].a), d = pt(pslg.segments[j].b);
    int o1 = CGAL::orientation(a, b, c), o2 = CGAL::orientation(a, b, d);
    int o3 = CGAL::orientation(c, d, a), o4 = CGAL::orientation(c, d, b);
    if (o1 * o2 < 0 && o3 * o4 < 0)
      throw InputError(pslg.source, line_at(pslg.segment_lines, s),
                       fmt::format("segments {} and {}{} cross; segments may meet only at vertices (option --split-crossings splits them at the intersection)", s + 1, j + 1,
                                   at_line(pslg.segment_lines, j)));
  }
  throw InputError(pslg.source, line_at(pslg.segment_lines, s),
                   fmt::format("segment {} crosses an earlier segment; segments may meet only at vertices (option --split-crossings splits them at the intersection)", s + 1));
}

// The constrained edges around each vertex, sorted by direction, so that the
// walk along a segment finds its next vertex in O(log degree) even at a vertex
// where 10^5 segments meet (a star, a wheel of diameters).
class ConstrainedStar {
 public:
  ConstrainedStar(const Cdt& cdt, const std::vector<Vh>& handle) : around_(handle.size()) {
    for (const Cdt::Edge& e : cdt.finite_edges()) {
      if (!cdt.is_constrained(e)) continue;
      Vh u = e.first->vertex(Cdt::cw(e.second)), w = e.first->vertex(Cdt::ccw(e.second));
      around_[static_cast<std::size_t>(u->info())].push_back(w);
      around_[static_cast<std::size_t>(w->info())].push_back(u);
    }
    for (std::size_t v = 0; v < handle.size(); ++v) {
      const K::Point_2& o = handle[v]->point();
      std::sort(around_[v].begin(), around_[v].end(), [&](Vh p, Vh q) { return before(o, p->point(), q->point()); });
    }
  }

  // The vertex after `from` on the constrained path toward `toward` (a point on
  // a line through a chain of constrained edges from `from`), or null if none.
  Vh next(Vh from, const K::Point_2& toward) const {
    const std::vector<Vh>& list = around_[static_cast<std::size_t>(from->info())];
    const K::Point_2& o = from->point();
    auto it = std::lower_bound(list.begin(), list.end(), toward,
                               [&](Vh p, const K::Point_2& t) { return before(o, p->point(), t); });
    if (it == list.end() || before(o, toward, (*it)->point())) return Vh();
    return *it;  // the constrained edge in exactly that direction
  }

 private:
  // Exact angular order of the directions p - o and q - o, counter-clockwise
  // from the positive x axis: the half-plane first, then the orientation.
  static bool before(const K::Point_2& o, const K::Point_2& p, const K::Point_2& q) {
    auto upper = [&](const K::Point_2& r) { return r.y() > o.y() || (r.y() == o.y() && r.x() > o.x()); };
    const bool up = upper(p), uq = upper(q);
    if (up != uq) return up;
    return CGAL::orientation(o, p, q) == CGAL::LEFT_TURN;
  }

  std::vector<std::vector<Vh>> around_;
};

// The vertices along the constrained segment a-b, a first, b last.
std::vector<int> chain_of(const ConstrainedStar& star, Vh a, Vh b) {
  std::vector<int> chain{a->info()};
  for (Vh cur = a; cur != b;) {
    Vh next = star.next(cur, b->point());
    if (next == Vh()) throw std::logic_error("validate: an inserted segment is not a chain of constrained edges");
    chain.push_back(next->info());
    cur = next;
  }
  return chain;
}

void flood(std::deque<Fh>& queue, int state) {
  while (!queue.empty()) {
    Fh f = queue.front();
    queue.pop_front();
    for (int i = 0; i < 3; ++i) {
      Fh n = f->neighbor(i);
      if (!f->is_constrained(i) && n->info() == kInDomain) {
        n->info() = state;
        queue.push_back(n);
      }
    }
  }
}

}  // namespace

void check_geometry(Pslg& pslg, std::vector<std::string>& warnings) {
  const std::string& file = pslg.source;
  Cdt cdt;
  std::vector<Vh> handle(pslg.vertices.size());
  {
    // Insert in spatial order (Hilbert sort), each located from the last: O(n log n).
    std::vector<K::Point_2> points;
    points.reserve(pslg.vertices.size());
    for (const Point& p : pslg.vertices) points.push_back(to_cgal(p));
    std::vector<std::size_t> order(points.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    using Traits = CGAL::Spatial_sort_traits_adapter_2<K, CGAL::Pointer_property_map<K::Point_2>::type>;
    CGAL::spatial_sort(order.begin(), order.end(), Traits(CGAL::make_property_map(points)));
    Fh hint;
    for (std::size_t i : order) {
      Vh v = cdt.insert(points[i], hint);
      v->info() = static_cast<int>(i);
      handle[i] = v;
      hint = v->face();
    }
  }
  if (cdt.dimension() < 2)
    throw InputError(file, 0,
                     pslg.vertices.size() < 3
                         ? fmt::format("fewer than three non-collinear vertices (only {} distinct): nothing to triangulate",
                                       pslg.vertices.size())
                         : fmt::format("fewer than three non-collinear vertices (all {} distinct vertices lie on one "
                                       "line): nothing to triangulate",
                                       pslg.vertices.size()));

  // CGAL starts a constraint by circling its first vertex: start each from the
  // endpoint with fewer segments, so a hub with 10^5 spokes costs O(n), not O(n^2).
  std::vector<std::uint32_t> segments_at(pslg.vertices.size(), 0);
  for (const Segment& seg : pslg.segments) ++segments_at[static_cast<std::size_t>(seg.a)], ++segments_at[static_cast<std::size_t>(seg.b)];
  for (std::size_t s = 0; s < pslg.segments.size(); ++s) {
    std::size_t a = static_cast<std::size_t>(pslg.segments[s].a), b = static_cast<std::size_t>(pslg.segments[s].b);
    if (segments_at[a] > segments_at[b]) std::swap(a, b);
    try {
      cdt.insert_constraint(handle[a], handle[b]);
    } catch (const Cdt::Intersection_of_constraints_exception&) {
      report_crossing(pslg, s);
    }
  }

  // Each segment becomes the pieces between the vertices on it; a piece
  // already owned by an earlier segment (a repeat or an overlap) is kept once.
  std::vector<Segment> pieces;
  std::vector<int> piece_lines, piece_origin;
  std::unordered_map<std::uint64_t, std::size_t> owner;  // piece (min id, max id) -> input segment
  owner.reserve(pslg.segments.size() * 2);
  WarningSink splits(warnings, "vertex inside a segment"), repeats(warnings, "repeated segment"),
      overlaps(warnings, "overlapping segments");
  const ConstrainedStar star(cdt, handle);
  for (std::size_t s = 0; s < pslg.segments.size(); ++s) {
    const Segment& seg = pslg.segments[s];
    std::vector<int> chain =
        chain_of(star, handle[static_cast<std::size_t>(seg.a)], handle[static_cast<std::size_t>(seg.b)]);
    const std::string here = where(file, line_at(pslg.segment_lines, s));
    if (chain.size() > 2) {
      std::size_t v = static_cast<std::size_t>(chain[1]);
      splits.add(fmt::format("{}: segment {} passes through vertex {}{}{}; split there", here, s + 1, v + 1,
                             at_line(pslg.vertex_lines, v),
                             chain.size() > 3 ? fmt::format(" and {} more", chain.size() - 3) : std::string()));
    }
    std::size_t covered = 0, earlier = 0;
    for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
      int u = std::min(chain[k], chain[k + 1]), w = std::max(chain[k], chain[k + 1]);
      std::uint64_t key = (static_cast<std::uint64_t>(u) << 32) | static_cast<std::uint32_t>(w);
      auto [it, fresh] = owner.emplace(key, s);
      if (!fresh) {
        if (covered++ == 0) earlier = it->second;
        continue;
      }
      pieces.push_back({chain[k], chain[k + 1], seg.marker});
      piece_lines.push_back(line_at(pslg.segment_lines, s));
      piece_origin.push_back(s < pslg.segment_origin.size() ? pslg.segment_origin[s] : static_cast<int>(s));
    }
    if (covered == 0) continue;
    const std::string other = fmt::format("segment {}{}", earlier + 1, at_line(pslg.segment_lines, earlier));
    if (chain.size() == 2)
      repeats.add(fmt::format("{}: segment {} repeats {}; dropped", here, s + 1, other));
    else if (covered + 1 == chain.size())
      overlaps.add(fmt::format("{}: segment {} lies along earlier segments (first {}); dropped", here, s + 1, other));
    else
      overlaps.add(fmt::format("{}: segment {} overlaps {} along a collinear stretch; the shared part is kept once",
                               here, s + 1, other));
  }
  pslg.segments = std::move(pieces);
  pslg.segment_lines = std::move(piece_lines);
  pslg.segment_origin = std::move(piece_origin);

  // The domain, as ALGORITHM.md section 2 defines it: flood from outside the
  // convex hull, then from each hole point, never across a constrained edge.
  for (Fh f : cdt.all_face_handles()) f->info() = kInDomain;
  std::deque<Fh> queue;
  {
    Cdt::Face_circulator f = cdt.incident_faces(cdt.infinite_vertex()), done = f;
    do {
      f->info() = kOutside;
      queue.push_back(f);
    } while (++f != done);
  }
  flood(queue, kOutside);
  WarningSink useless_holes(warnings, "hole point that removes nothing");
  Fh hint;
  for (std::size_t h = 0; h < pslg.holes.size(); ++h) {
    Cdt::Locate_type type;
    int li = 0;
    Fh f = cdt.locate(to_cgal(pslg.holes[h]), type, li, hint);
    hint = f;
    const std::string here = where(file, line_at(pslg.hole_lines, h));
    if (type == Cdt::VERTEX) {
      useless_holes.add(fmt::format("{}: hole point {} lies on vertex {}; it removes nothing", here, h + 1,
                                    f->vertex(li)->info() + 1));
    } else if (type == Cdt::EDGE && f->is_constrained(li)) {
      useless_holes.add(fmt::format("{}: hole point {} lies on a segment; it removes nothing", here, h + 1));
    } else if (type == Cdt::OUTSIDE_CONVEX_HULL || type == Cdt::OUTSIDE_AFFINE_HULL || f->info() == kOutside) {
      useless_holes.add(fmt::format("{}: hole point {} lies outside the domain; it removes nothing", here, h + 1));
    } else if (f->info() == kInDomain) {
      f->info() = kInHole;
      queue.push_back(f);
      flood(queue, kInHole);
    }
  }
  // A region point with an area bound where no triangle is reached from it:
  // the engines set nothing there (ALGORITHM.md section 2), as for hole points.
  WarningSink useless_regions(warnings, "region point whose area bound applies to nothing");
  for (std::size_t r = 0; r < pslg.regions.size(); ++r) {
    if (!(pslg.regions[r].max_area > 0)) continue;
    Cdt::Locate_type type;
    int li = 0;
    Fh f = cdt.locate(to_cgal(pslg.regions[r].at), type, li, hint);
    const std::string here = where(file, line_at(pslg.region_lines, r));
    const char* why = nullptr;
    if (type == Cdt::VERTEX) why = "on a vertex";
    else if (type == Cdt::EDGE && f->is_constrained(li)) why = "on a segment";
    else if (type == Cdt::OUTSIDE_CONVEX_HULL || type == Cdt::OUTSIDE_AFFINE_HULL || f->info() == kOutside) why = "outside the domain";
    else if (f->info() == kInHole) why = "in a hole";
    if (why) useless_regions.add(fmt::format("{}: region point {} lies {}; its area bound applies to nothing", here, r + 1, why));
  }
  bool any = false;
  for (Fh f : cdt.finite_face_handles()) any = any || f->info() == kInDomain;
  if (!any)
    throw InputError(file, 0,
                     pslg.holes.empty() ? "the domain is empty: no region is enclosed by segments (nothing to mesh; option "
                                          "--convex-hull encloses the convex hull)"
                                        : "the domain is empty: no region is enclosed by segments, or the hole points "
                                          "remove all of it (nothing to mesh)");
}

}  // namespace lepp::detail
