// SPDX-License-Identifier: GPL-3.0-or-later
// What can block a sliver split (sliver_obstacles.h): an R-tree of the input's
// segments and lone vertices, and each segment's chain of vertices in order.
#include "sliver_obstacles.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <boost/geometry/geometries/box.hpp>
#include <boost/geometry/geometries/point.hpp>
#include <boost/geometry/index/rtree.hpp>

#include "predicates.h"

namespace lepp::fast {
namespace {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using BoxPoint = bg::model::point<double, 2, bg::cs::cartesian>;
using Box = bg::model::box<BoxPoint>;
using Entry = std::pair<Box, int>;  // a segment's id, or ~v for input vertex v on no segment

Box box_of(const Point& u, const Point& w) {
  return Box(BoxPoint(std::min(u.x, w.x), std::min(u.y, w.y)), BoxPoint(std::max(u.x, w.x), std::max(u.y, w.y)));
}

// A segment's vertices from its first endpoint to its second. Every split puts a
// rounded midpoint of a subsegment u, w (or another rounding of it: the doubles
// around the exact midpoint) between u and w in each coordinate, as rounding a
// value between two doubles gives one between them; so along the chain both
// coordinates are monotone, and the chain stays in the segment's bounding box
// (which is why the R-tree of the input segments' boxes needs no margin for the
// subsegments' drift off their line). Ordered by the coordinate along which the
// segment runs farther, directed from first to second endpoint, then the other.
struct Chain {
  std::vector<int> ids;
  bool along_y = false;
  double sx = 1, sy = 1;  // the segment's direction in each coordinate, +1 or -1

  double primary(const Point& q) const { return along_y ? sy * q.y : sx * q.x; }
  double secondary(const Point& q) const { return along_y ? sx * q.x : sy * q.y; }
  bool before(const Point& q, const Point& r) const {
    const double pq = primary(q), pr = primary(r);
    return pq < pr || (pq == pr && secondary(q) < secondary(r));
  }
};

}  // namespace

struct SliverObstacles::Index {
  bgi::rtree<Entry, bgi::quadratic<16>> tree;
  std::vector<Chain> chains;
  std::vector<Entry> hits;  // one query's, reused
};

SliverObstacles::SliverObstacles(const Pslg& pslg, const SegmentMembership& membership) : pslg_(pslg), mem_(membership) {}
SliverObstacles::~SliverObstacles() = default;

void SliverObstacles::add_to_chain(const TriMesh& m, int segment, int v) {
  Chain& c = index_->chains[static_cast<std::size_t>(segment)];
  const Point& q = m.p(v);
  const auto at = std::lower_bound(c.ids.begin() + 1, c.ids.end() - 1, v, [&](int x, int) { return c.before(m.p(x), q); });
  c.ids.insert(at, v);
}

bool SliverObstacles::blocks(const TriMesh& m, int va, int vb, const Point& p) {
  const auto [known, fresh] = answers_.try_emplace({va, vb, p.x, p.y}, false);
  if (!fresh) return known->second;
  return known->second = test(m, va, vb, p);
}

bool SliverObstacles::test(const TriMesh& m, int va, int vb, const Point& p) {
  if (!index_) {
    index_ = std::make_unique<Index>();
    std::vector<Chain>& chains = index_->chains;
    chains.resize(pslg_.segments.size());
    const int n = mem_.input_vertices;
    std::vector<std::size_t> count(chains.size(), 2);
    for (const auto& [k, s] : mem_.steiner_segments) ++count[static_cast<std::size_t>(s)];
    std::vector<Entry> entries;
    entries.reserve(chains.size());
    for (std::size_t s = 0; s < chains.size(); ++s) {
      Chain& c = chains[s];
      const Segment& g = pslg_.segments[s];
      const Point &u = m.p(g.a), &w = m.p(g.b);
      c.sx = w.x >= u.x ? 1 : -1;
      c.sy = w.y >= u.y ? 1 : -1;
      c.along_y = std::fabs(w.y - u.y) > std::fabs(w.x - u.x);
      c.ids.reserve(count[s]);
      c.ids.push_back(g.a);
      entries.push_back({box_of(u, w), static_cast<int>(s)});
    }
    for (const auto& [k, s] : mem_.steiner_segments) chains[static_cast<std::size_t>(s)].ids.push_back(n + k);
    for (std::size_t s = 0; s < chains.size(); ++s) {
      Chain& c = chains[s];
      std::sort(c.ids.begin() + 1, c.ids.end(), [&](int x, int y) { return c.before(m.p(x), m.p(y)); });
      c.ids.push_back(pslg_.segments[s].b);
    }
    for (int v = 0; v < n; ++v)
      if (!mem_.on_any(v)) entries.push_back({box_of(m.p(v), m.p(v)), ~v});
    index_->tree = bgi::rtree<Entry, bgi::quadratic<16>>(entries.begin(), entries.end());  // bulk loaded
  }

  const Point &a = m.p(va), &b = m.p(vb);
  const double x0 = std::min({a.x, b.x, p.x}), x1 = std::max({a.x, b.x, p.x});
  const double y0 = std::min({a.y, b.y, p.y}), y1 = std::max({a.y, b.y, p.y});
  std::vector<Entry>& hits = index_->hits;
  hits.clear();
  index_->tree.query(bgi::intersects(Box(BoxPoint(x0, y0), BoxPoint(x1, y1))), std::back_inserter(hits));
  auto in_box = [&](const Point& q) { return x0 <= q.x && q.x <= x1 && y0 <= q.y && q.y <= y1; };
  // ab's own segment has nothing else there: its chain is monotone in both coordinates,
  // so the boxes of its other edges meet ab's box (which holds the triangle) at a or b only.
  const int own = mem_.segment_of(va, vb);
  near_.vertices.clear();
  near_.segments.clear();
  for (const Entry& e : hits) {
    if (e.second < 0) {
      near_.vertices.push_back(m.p(~e.second));
      continue;
    }
    if (e.second == own) continue;
    // The chain edges whose extent along the primary coordinate meets the triangle's:
    // edge i (ids[i], ids[i + 1]) from the last vertex before the range to the first after it.
    const Chain& c = index_->chains[static_cast<std::size_t>(e.second)];
    const double lo = c.along_y ? (c.sy > 0 ? y0 : -y1) : (c.sx > 0 ? x0 : -x1);
    const double hi = c.along_y ? (c.sy > 0 ? y1 : -y0) : (c.sx > 0 ? x1 : -x0);
    const auto first = std::lower_bound(c.ids.begin(), c.ids.end(), lo, [&](int v, double t) { return c.primary(m.p(v)) < t; });
    const auto past = std::upper_bound(c.ids.begin(), c.ids.end(), hi, [&](double t, int v) { return t < c.primary(m.p(v)); });
    const std::ptrdiff_t from = std::max<std::ptrdiff_t>(first - c.ids.begin() - 1, 0);
    const std::ptrdiff_t to = std::min<std::ptrdiff_t>(past - c.ids.begin(), static_cast<std::ptrdiff_t>(c.ids.size()) - 1);
    for (std::ptrdiff_t i = from; i <= to; ++i) {
      const Point& q = m.p(c.ids[static_cast<std::size_t>(i)]);
      if (in_box(q)) near_.vertices.push_back(q);
      if (i == to) break;
      const Point& r = m.p(c.ids[static_cast<std::size_t>(i + 1)]);
      if (std::max(q.x, r.x) >= x0 && std::min(q.x, r.x) <= x1 && std::max(q.y, r.y) >= y0 && std::min(q.y, r.y) <= y1)
        near_.segments.push_back({q, r});  // only an edge whose box meets the triangle's can meet it
    }
  }
  return sliver_blocked(near_, a, b, p, [](const Point& x, const Point& y, const Point& z) { return orient(x, y, z); });
}

}  // namespace lepp::fast
