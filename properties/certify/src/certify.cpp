// SPDX-License-Identifier: GPL-3.0-or-later
// The checks, in the order docs/CERTIFIER.md lists them. Every decision is an
// exact sign (exact.h); doubles appear only in messages and statistics.
#include "lepp/certify.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <cstring>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <map>
#include <set>

#include <fmt/format.h>

#include "chain_embedding.h"
#include "exact.h"
#include "expected_domain.h"
#include "precision_limit.h"
#include "small_input_angles_internal.h"
#include "lepp/angle.h"
#include "lepp/stats.h"

namespace lepp::certify {
namespace {

constexpr std::size_t kReasons = static_cast<std::size_t>(Reason::AreaAboveBound) + 1;

std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}
// The ends of edge_key's edge (smaller id first).
std::array<int, 2> edge_ends(std::uint64_t key) { return {static_cast<int>(key >> 32), static_cast<int>(key & 0xffffffffu)}; }

std::string pt(const Point& p) { return fmt::format("({}, {})", p.x, p.y); }

struct PointHash {
  std::size_t operator()(const Point& p) const {
    // Hashed by value, as Point's == compares: -0 and +0 are one point (adding +0.0
    // turns -0.0 into +0.0), so a mesher that prints -0 as 0 keeps its input vertex.
    const double px = p.x + 0.0, py = p.y + 0.0;
    std::uint64_t x = 0, y = 0;
    std::memcpy(&x, &px, sizeof x);
    std::memcpy(&y, &py, sizeof y);
    return std::hash<std::uint64_t>()(x * 0x9E3779B97F4A7C15ull ^ y);
  }
};

class Certifier {
 public:
  Certifier(const Pslg& pslg, const Mesh& mesh, const Options& options, Report& report)
      : pslg_(pslg), mesh_(mesh), opt_(options), report_(report) {}

  void run() {
    report_.count_by_reason.assign(kReasons, 0);
    report_.min_angle_deg = opt_.min_angle_deg;
    check_triangles();
    build_edges();
    check_duplicate_vertices();
    domain_ = expected_domain(pslg_);
    collect_outside_input();
    map_input_vertices();
    check_unused_vertices();
    check_outside_vertices_uncovered();
    build_adjacency();
    find_chains();
    check_split_points();
    check_listed_constrained_edges();
    check_coverage();
    check_chains_cross_nowhere();
    check_euler();
    compute_longest_edges();
    check_delaunay();
    if (opt_.exempt_small_input_angles) report_.small_angles = small_input_angles(pslg_, domain_);
    if (opt_.min_angle_deg > 0) check_angles();
    if (opt_.theorem2) check_theorem2();
    if (opt_.region_area_bounds) assign_regions();
    if (opt_.max_area > 0 || opt_.region_area_bounds) check_area_bounds();
    compute_statistics();
  }

 private:
  const Pslg& pslg_;
  const Mesh& mesh_;
  const Options& opt_;
  Report& report_;
  ExpectedDomain domain_;
  OutsideInput outside_;               // the input outside the domain (collect_outside_input)
  std::vector<std::array<int, 2>> chain_edges_;  // chain_edge_'s edges sorted by key (find_chains), and
  std::vector<int> chain_edge_segment_;          // the segment of each
  OutsideInput chain_segments_;        // the same edges as segments (the exemption's sliver clause)

  std::vector<char> tri_ok_;           // ids valid (orientation may still be wrong)
  std::vector<int> twin_;              // half-edge 3t+i (t[i] -> t[i+1]): opposite half, -1 boundary, -2 bad edge
  std::vector<std::array<int, 2>> edges_;  // unique edges (a < b) of valid triangles
  std::vector<char> used_;
  std::vector<char> merged_;           // an unused exact duplicate of an input vertex (check_duplicate_vertices)
  std::vector<int> input_to_mesh_;     // input vertex id -> mesh vertex id, -1 missing
  std::vector<int> mesh_to_input_;     // mesh vertex id -> input vertex id, -1 Steiner
  std::vector<int> adj_begin_, adj_;   // vertex adjacency (CSR)
  std::unordered_map<std::uint64_t, int> listed_;  // listed constrained edge -> its segment id (-1 unknown)
  std::unordered_map<std::uint64_t, int> chain_edge_;  // edge on a segment chain -> segment id
  std::vector<std::vector<int>> chains_;  // per segment: mesh vertex ids from a to b, empty if not found
  std::vector<int> vertex_segment_;    // Steiner vertex -> the segment whose chain it is inside, -1 none
  std::vector<char> constrained_half_;
  std::vector<signed char> longest_;   // per triangle: index i of its longest half-edge

  const Point& P(int v) const { return mesh_.vertices[static_cast<std::size_t>(v)]; }
  const Tri& T(std::size_t t) const { return mesh_.triangles[t]; }
  int from(int h) const { return T(static_cast<std::size_t>(h / 3))[static_cast<std::size_t>(h % 3)]; }
  int to(int h) const { return T(static_cast<std::size_t>(h / 3))[static_cast<std::size_t>((h % 3 + 1) % 3)]; }
  int apex(int h) const { return T(static_cast<std::size_t>(h / 3))[static_cast<std::size_t>((h % 3 + 2) % 3)]; }

  void add(Violation v) {
    std::size_t r = static_cast<std::size_t>(v.reason);
    if (report_.count_by_reason[r]++ < opt_.max_listed_per_reason) {
      for (int id : v.vertices)
        if (id >= 0 && static_cast<std::size_t>(id) < mesh_.vertices.size() && v.points.size() < v.vertices.size())
          v.points.push_back(P(id));
      report_.violations.push_back(std::move(v));
    }
  }
  std::string tri_text(std::size_t t) const {
    const Tri& x = T(t);
    return fmt::format("triangle {} ({} {} {}: {} {} {})", t, x[0], x[1], x[2], pt(P(x[0])), pt(P(x[1])), pt(P(x[2])));
  }

  // --- 1. Topology -------------------------------------------------------
  void check_triangles() {
    const int n = static_cast<int>(mesh_.vertices.size());
    tri_ok_.assign(mesh_.triangles.size(), 0);
    for (std::size_t t = 0; t < mesh_.triangles.size(); ++t) {
      const Tri& x = T(t);
      bool ids = true;
      for (int v : x) ids = ids && v >= 0 && v < n;
      if (!ids || x[0] == x[1] || x[1] == x[2] || x[0] == x[2]) {
        add({Reason::BadTriangle, fmt::format("triangle {} has vertex ids {} {} {} (out of range or repeated)", t, x[0], x[1], x[2]),
             {static_cast<int>(t)}, {}, {}, {}, -1});
        continue;
      }
      if (!finite(P(x[0])) || !finite(P(x[1])) || !finite(P(x[2]))) {
        add({Reason::BadTriangle, fmt::format("{} has a NaN or infinite coordinate", tri_text(t)), {static_cast<int>(t)}, {}, {}, {}, -1});
        continue;
      }
      tri_ok_[t] = 1;
      if (exact::orient(P(x[0]), P(x[1]), P(x[2])) <= 0)
        add({Reason::NotCounterClockwise, fmt::format("{} is not strictly counter-clockwise", tri_text(t)),
             {static_cast<int>(t)}, {}, {x[0], x[1], x[2]}, {}, -1});
    }
  }

  void build_edges() {
    struct Half {
      std::uint64_t key;
      int h;
    };
    std::vector<Half> halves;
    halves.reserve(mesh_.triangles.size() * 3);
    for (std::size_t t = 0; t < mesh_.triangles.size(); ++t)
      if (tri_ok_[t])
        for (int i = 0; i < 3; ++i) {
          int h = static_cast<int>(3 * t) + i;
          halves.push_back({edge_key(from(h), to(h)), h});
        }
    std::sort(halves.begin(), halves.end(), [](const Half& x, const Half& y) { return x.key < y.key || (x.key == y.key && x.h < y.h); });
    twin_.assign(mesh_.triangles.size() * 3, -1);
    used_.assign(mesh_.vertices.size(), 0);
    for (std::size_t i = 0; i < halves.size();) {
      std::size_t j = i;
      while (j < halves.size() && halves[j].key == halves[i].key) ++j;
      const int a = from(halves[i].h), b = to(halves[i].h);
      edges_.push_back({std::min(a, b), std::max(a, b)});
      used_[static_cast<std::size_t>(a)] = used_[static_cast<std::size_t>(b)] = 1;
      if (j - i > 2) {
        Violation v{Reason::EdgeOverused, fmt::format("edge {}-{} {} {} lies in {} triangles (overlap)", a, b, pt(P(a)), pt(P(b)), j - i),
                    {}, {{a, b}}, {a, b}, {}, -1};
        for (std::size_t k = i; k < j; ++k) {
          v.triangles.push_back(halves[k].h / 3);
          twin_[static_cast<std::size_t>(halves[k].h)] = -2;
        }
        add(std::move(v));
      } else if (j - i == 2) {
        const int h0 = halves[i].h, h1 = halves[i + 1].h;
        if (from(h0) == from(h1)) {
          add({Reason::EdgeSameDirection,
               fmt::format("edge {}-{} {} {} is traversed the same way by triangles {} and {} (overlap or fold)", from(h0), to(h0),
                           pt(P(from(h0))), pt(P(to(h0))), h0 / 3, h1 / 3),
               {h0 / 3, h1 / 3}, {{from(h0), to(h0)}}, {from(h0), to(h0)}, {}, -1});
          twin_[static_cast<std::size_t>(h0)] = twin_[static_cast<std::size_t>(h1)] = -2;
        } else {
          twin_[static_cast<std::size_t>(h0)] = h1;
          twin_[static_cast<std::size_t>(h1)] = h0;
        }
      }
      i = j;
    }
  }

  static bool finite(const Point& p) { return std::isfinite(p.x) && std::isfinite(p.y); }

  // Mesh vertices with the same coordinates are a violation, except an exact
  // duplicate of an input vertex that no triangle uses: Triangle keeps an input's
  // repeated vertex in its .node, unused, and meshes with one copy (as lepp's
  // validate merges it). Such a copy is merged into the one in use, with a warning.
  void check_duplicate_vertices() {
    std::vector<int> order;
    for (std::size_t i = 0; i < mesh_.vertices.size(); ++i)
      if (finite(mesh_.vertices[i])) order.push_back(static_cast<int>(i));  // NaN breaks the sort's order
    auto less = [&](int a, int b) { return P(a).x < P(b).x || (P(a).x == P(b).x && P(a).y < P(b).y); };
    std::sort(order.begin(), order.end(), less);
    std::unordered_set<Point, PointHash> input(pslg_.vertices.begin(), pslg_.vertices.end());
    merged_.assign(mesh_.vertices.size(), 0);
    for (std::size_t i = 0; i < order.size();) {
      std::size_t j = i + 1;
      while (j < order.size() && P(order[j]) == P(order[i])) ++j;
      std::size_t in_use = 0;
      for (std::size_t k = i; k < j; ++k) in_use += used_[static_cast<std::size_t>(order[k])];
      if (j - i > 1 && in_use <= 1 && input.count(P(order[i]))) {
        // The copy the triangles use (else the first) stands for the input vertex.
        int kept = order[i];
        for (std::size_t k = i; k < j; ++k)
          if (used_[static_cast<std::size_t>(order[k])]) kept = order[k];
        for (std::size_t k = i; k < j; ++k)
          if (order[k] != kept) {
            merged_[static_cast<std::size_t>(order[k])] = 1;
            report_.warnings.push_back(fmt::format("mesh vertex {} duplicates mesh vertex {} {}, an input vertex, and is in no triangle; merged",
                                                   order[k], kept, pt(P(kept))));
          }
      } else {
        for (std::size_t k = i + 1; k < j; ++k)
          add({Reason::DuplicateMeshVertex,
               fmt::format("mesh vertices {} and {} have the same coordinates {}", order[k - 1], order[k], pt(P(order[k]))), {}, {},
               {order[k - 1], order[k]}, {}, -1});
      }
      i = j;
    }
  }

  // --- 2. Input preservation ----------------------------------------------
  void map_input_vertices() {
    const std::size_t n = pslg_.vertices.size();
    input_to_mesh_.assign(n, -1);
    mesh_to_input_.assign(mesh_.vertices.size(), -1);
    std::unordered_map<Point, int, PointHash> where;
    where.reserve(mesh_.vertices.size() * 2);
    for (std::size_t i = mesh_.vertices.size(); i-- > 0;)
      if (!merged_[i]) where[mesh_.vertices[i]] = static_cast<int>(i);  // the first copy not merged away
    for (std::size_t i = 0; i < n; ++i) {
      const Point& p = pslg_.vertices[i];
      if (i < mesh_.input_vertices) {
        // The mesh promises vertex i is input vertex i: coordinates must be bit-identical.
        if (i >= mesh_.vertices.size() || mesh_.vertices[i] != p) {
          add({Reason::InputVertexMoved,
               fmt::format("input vertex {} {} is mesh vertex {} at {}", i, pt(p), i,
                           i < mesh_.vertices.size() ? pt(mesh_.vertices[i]) : std::string("(absent)")),
               {}, {}, {static_cast<int>(i)}, {p}, -1});
        }
        if (i < mesh_.vertices.size()) input_to_mesh_[i] = static_cast<int>(i);
      } else {
        auto it = where.find(p);
        if (it != where.end()) input_to_mesh_[i] = it->second;
        else if (i + pslg_.crossing_vertices >= n) input_to_mesh_[i] = nearest_mesh_vertex(p);
      }
      const int m = input_to_mesh_[i];
      if (m >= 0) mesh_to_input_[static_cast<std::size_t>(m)] = static_cast<int>(i);
      const bool moved = m >= 0 && mesh_.vertices[static_cast<std::size_t>(m)] != p;
      const bool present = m >= 0 && used_[static_cast<std::size_t>(m)];
      if (!present && (!moved || i + pslg_.crossing_vertices >= n) && domain_.vertex_in_domain[i])
        add({Reason::InputVertexMissing, fmt::format("input vertex {} {} (in the domain) is not a vertex of any triangle", i, pt(p)),
             {}, {}, {static_cast<int>(i)}, {p}, -1});
    }
    if (mesh_.input_vertices > n)
      add({Reason::InputVertexMoved,
           fmt::format("the mesh claims {} input vertices, the input has {}", mesh_.input_vertices, n), {}, {}, {}, {}, -1});
  }

  // A crossing point another mesher rounded otherwise: the mesh vertex nearest
  // to ours, if within 2^-40 of it (relative). Only a candidate: check_split_points
  // then holds it to the chain tolerance of both segments. Linear: crossing
  // points missing exactly are few.
  int nearest_mesh_vertex(const Point& p) const {
    const double radius = std::ldexp(std::max({1.0, std::abs(p.x), std::abs(p.y)}), -40);
    int best = -1;
    double best_d = radius;
    for (std::size_t v = 0; v < mesh_.vertices.size(); ++v) {
      const double d = std::max(std::abs(mesh_.vertices[v].x - p.x), std::abs(mesh_.vertices[v].y - p.y));
      if (d <= best_d) best = static_cast<int>(v), best_d = d;
    }
    return best;
  }

  void check_unused_vertices() {
    for (std::size_t v = 0; v < mesh_.vertices.size(); ++v) {
      if (used_[v] || merged_[v]) continue;
      const int in = mesh_to_input_[v];
      if (in >= 0 && !domain_.vertex_in_domain[static_cast<std::size_t>(in)]) continue;  // outside the domain: may be unused
      if (in >= 0) continue;  // reported as InputVertexMissing
      add({Reason::UnusedVertex, fmt::format("Steiner vertex {} {} is in no triangle", v, pt(P(static_cast<int>(v)))), {}, {},
           {static_cast<int>(v)}, {}, -1});
    }
  }

  // An input vertex outside the domain may be in no triangle, but then must lie in
  // none: a triangle covering it (on its closed area, not at a corner) makes the
  // mesh no triangulation of its vertices there. The coverage checks count sides
  // of segments and the Euler characteristic, which a vertex in no triangle does
  // not enter, so they do not see it (a boundary split whose rounded midpoint,
  // half an ulp outside, takes such a vertex into its sliver: ALGORITHM.md
  // section 8b). Sweep by x: such vertices are few, usually none.
  void check_outside_vertices_uncovered() {
    std::vector<int> loose;  // input ids: outside the domain, a vertex of no triangle
    for (std::size_t i = 0; i < pslg_.vertices.size(); ++i) {
      const int m = input_to_mesh_[i];
      if (!domain_.vertex_in_domain[i] && (m < 0 || !used_[static_cast<std::size_t>(m)])) loose.push_back(static_cast<int>(i));
    }
    if (loose.empty()) return;
    auto X = [&](int i) { return pslg_.vertices[static_cast<std::size_t>(i)].x; };
    std::sort(loose.begin(), loose.end(), [&](int i, int j) { return X(i) < X(j); });
    for (std::size_t t = 0; t < mesh_.triangles.size(); ++t) {
      if (!tri_ok_[t]) continue;
      const Point &a = P(T(t)[0]), &b = P(T(t)[1]), &c = P(T(t)[2]);
      if (!finite(a) || !finite(b) || !finite(c) || exact::orient(a, b, c) <= 0) continue;  // reported in section 1
      const double x0 = std::min({a.x, b.x, c.x}), x1 = std::max({a.x, b.x, c.x});
      const double y0 = std::min({a.y, b.y, c.y}), y1 = std::max({a.y, b.y, c.y});
      auto it = std::lower_bound(loose.begin(), loose.end(), x0, [&](int i, double x) { return X(i) < x; });
      for (; it != loose.end() && X(*it) <= x1; ++it) {
        const Point& q = pslg_.vertices[static_cast<std::size_t>(*it)];
        if (q.y < y0 || q.y > y1 || q == a || q == b || q == c) continue;
        if (exact::orient(a, b, q) < 0 || exact::orient(b, c, q) < 0 || exact::orient(c, a, q) < 0) continue;
        add({Reason::InputVertexMissing,
             fmt::format("input vertex {} {} (outside the domain) lies on {} but is not one of its vertices", *it, pt(q), tri_text(t)),
             {static_cast<int>(t)}, {}, {*it}, {q}, -1});
      }
    }
  }

  // --- 3. Constrained edges ------------------------------------------------
  void build_adjacency() {
    adj_begin_.assign(mesh_.vertices.size() + 1, 0);
    for (const auto& e : edges_) {
      ++adj_begin_[static_cast<std::size_t>(e[0]) + 1];
      ++adj_begin_[static_cast<std::size_t>(e[1]) + 1];
    }
    for (std::size_t i = 1; i < adj_begin_.size(); ++i) adj_begin_[i] += adj_begin_[i - 1];
    adj_.assign(static_cast<std::size_t>(adj_begin_.back()), 0);
    std::vector<int> fill(adj_begin_.begin(), adj_begin_.end() - 1);
    for (const auto& e : edges_) {
      adj_[static_cast<std::size_t>(fill[static_cast<std::size_t>(e[0])]++)] = e[1];
      adj_[static_cast<std::size_t>(fill[static_cast<std::size_t>(e[1])]++)] = e[0];
    }
    for (const ConstrainedEdge& e : mesh_.constrained_edges) listed_[edge_key(e.a, e.b)] = e.segment;
  }

  bool adjacent(int v, int w) const {
    for (int i = adj_begin_[static_cast<std::size_t>(v)]; i < adj_begin_[static_cast<std::size_t>(v) + 1]; ++i)
      if (adj_[static_cast<std::size_t>(i)] == w) return true;
    return false;
  }

  // |cross(B - A, P - A)| <= tol * (|B.x - A.x| + |B.y - A.y|), exactly.
  static bool within(const Point& a, const Point& b, const Point& p, double tol) {
    return exact::sign([&](auto z) -> decltype(z) {
             using NT = decltype(z);
             NT dx = NT(b.x) - NT(a.x), dy = NT(b.y) - NT(a.y);
             NT cross = dx * (NT(p.y) - NT(a.y)) - dy * (NT(p.x) - NT(a.x));
             return CGAL::abs(cross) - NT(tol) * (CGAL::abs(dx) + CGAL::abs(dy));
           }) <= 0;
  }
  // |cross(B - A, P - A)| <= 2^-20 |AB|^2: P within 2^-20 |AB| of the line (to follow listed edges).
  static bool near_line(const Point& a, const Point& b, const Point& p) {
    return exact::sign([&](auto z) -> decltype(z) {
             using NT = decltype(z);
             NT dx = NT(b.x) - NT(a.x), dy = NT(b.y) - NT(a.y);
             NT cross = dx * (NT(p.y) - NT(a.y)) - dy * (NT(p.x) - NT(a.x));
             return CGAL::abs(cross) - NT(std::ldexp(1.0, -20)) * (dx * dx + dy * dy);
           }) <= 0;
  }
  // The step from p to q turns less from AB than the step from p to r (both ahead):
  // |cross(B - A, q - p)| / dot(B - A, q - p) < |cross(B - A, r - p)| / dot(B - A, r - p), exactly.
  static int compare_turn(const Point& a, const Point& b, const Point& p, const Point& q, const Point& r) {
    return exact::sign([&](auto z) -> decltype(z) {
      using NT = decltype(z);
      NT dx = NT(b.x) - NT(a.x), dy = NT(b.y) - NT(a.y);
      NT qx = NT(q.x) - NT(p.x), qy = NT(q.y) - NT(p.y), rx = NT(r.x) - NT(p.x), ry = NT(r.y) - NT(p.y);
      return CGAL::abs(dx * qy - dy * qx) * (dx * rx + dy * ry) - CGAL::abs(dx * ry - dy * rx) * (dx * qx + dy * qy);
    });
  }
  // sign(dot(q - p, B - A)): q ahead of p along AB.
  static int ahead(const Point& a, const Point& b, const Point& p, const Point& q) {
    return exact::sign([&](auto z) -> decltype(z) {
      using NT = decltype(z);
      return (NT(q.x) - NT(p.x)) * (NT(b.x) - NT(a.x)) + (NT(q.y) - NT(p.y)) * (NT(b.y) - NT(a.y));
    });
  }

  // The listed path from a to b, if exactly one: a listed edge from a, then at each
  // Steiner point its other listed edge (it has exactly two), every vertex strictly
  // ahead of the one before along AB, strictly before B and within 2^-20 |AB| of the
  // line or within the walk's loosest tolerance ((k+1) ulp: far from the origin one
  // ulp can be many times 2^-20 |AB|), up to an input vertex, which must be b. Empty when no listed path or more
  // than one leads from a to b. Where two segments leave a at a small angle and the
  // mesh is refined down to ulps of a, the first vertex of the other segment's chain
  // can be within one ulp of this segment's line and the straightest step; a walk that
  // took it followed the other chain until it left the line by 2^-20 |AB| and then
  // stepped across to this chain by an unlisted edge (docs/CERTIFIER.md section 3).
  // Which input vertex a listed path ends at tells the two chains apart exactly.
  std::vector<int> listed_path(int a, int b) const {
    if (listed_.empty()) return {};
    const Point &A = P(a), &B = P(b);
    const double loose = segment_tolerance(A, B, mesh_.vertices.size());
    const auto listed = [&](int v, int w) { return listed_.count(edge_key(v, w)) != 0; };
    std::vector<int> found;
    int paths = 0;
    for (int i = adj_begin_[static_cast<std::size_t>(a)]; i < adj_begin_[static_cast<std::size_t>(a) + 1]; ++i) {
      const int first = adj_[static_cast<std::size_t>(i)];
      if (!listed(a, first)) continue;
      std::vector<int> path{a};
      for (int prev = a, v = first;;) {
        if (v == b) {
          path.push_back(b);
          break;
        }
        if (mesh_to_input_[static_cast<std::size_t>(v)] >= 0 || ahead(A, B, P(prev), P(v)) <= 0 || ahead(A, B, P(v), B) <= 0 ||
            !(near_line(A, B, P(v)) || within(A, B, P(v), loose))) {
          path.clear();
          break;
        }
        path.push_back(v);
        int next = -1, listed_edges = 0;
        for (int j = adj_begin_[static_cast<std::size_t>(v)]; j < adj_begin_[static_cast<std::size_t>(v) + 1]; ++j) {
          const int w = adj_[static_cast<std::size_t>(j)];
          if (!listed(v, w)) continue;
          ++listed_edges;
          if (w != prev) next = w;
        }
        if (listed_edges != 2) {
          path.clear();
          break;
        }
        prev = v, v = next;
      }
      if (!path.empty()) ++paths, found = std::move(path);
    }
    if (paths != 1) found.clear();
    return found;
  }

  // Walks from a to b: the listed path, when exactly one leads from a to b; else at
  // each vertex the next vertex strictly ahead along AB and strictly before B, and no input vertex, tried in this order: the vertices
  // joined by a listed constrained edge within 1, 2, 4, ... ulp up to the loosest
  // tolerance, the straightest step first in each tier; then those joined by a
  // listed edge within 2^-20 |AB| of the line,
  // nearest first; then any within 1, 2, 4, ... ulp up to the loosest tolerance,
  // nearest first. Far from the origin the loosest tolerance ((k+1) ulp with k the
  // number of mesh vertices) reaches mesh vertices that are not on the segment.
  // Depth first: a step that leads nowhere is taken back and the next one tried
  // (where two nearly parallel segments leave one vertex, the straightest step may
  // be the other segment's, which ends past B: the notch family). A vertex from which
  // B was not reached is not tried again (what lies ahead of it does not depend on
  // the way there), so the walk visits each vertex once.
  // {-1, v} when there is no chain, v where the first choices stopped.
  std::vector<int> walk(int a, int b) const {
    if (std::vector<int> path = listed_path(a, b); !path.empty()) return path;
    const Point &A = P(a), &B = P(b);
    const double loose = segment_tolerance(A, B, mesh_.vertices.size());
    std::vector<double> tiers;  // 1, 2, 4, ... ulp, then the loosest
    for (std::size_t k = 0; k < mesh_.vertices.size(); k = 2 * k + 1) tiers.push_back(segment_tolerance(A, B, k));
    tiers.push_back(loose);
    // The steps from v, in the order they are tried.
    auto steps = [&](int v) {
      std::vector<int> ahead_of_v;
      for (int i = adj_begin_[static_cast<std::size_t>(v)]; i < adj_begin_[static_cast<std::size_t>(v) + 1]; ++i) {
        const int w = adj_[static_cast<std::size_t>(i)];
        // Never an input vertex: validate() split every segment at the input vertices
        // exactly on it, so one inside a segment is off it, however near.
        if (mesh_to_input_[static_cast<std::size_t>(w)] < 0 && ahead(A, B, P(v), P(w)) > 0 && ahead(A, B, P(w), B) > 0)
          ahead_of_v.push_back(w);
      }
      const auto listed = [&](int w) { return listed_.count(edge_key(v, w)) != 0; };
      const auto nearer = [&](int q, int r) { return ahead(A, B, P(q), P(r)) > 0; };
      // Far below the tolerance's scale (features of 1e-300 at a corner of a unit
      // square) a tier holds the first vertices of every segment that leaves v, and
      // the nearest ahead may be another segment's (the precision campaign,
      // docs/FUZZING.md): in the listed tiers the straightest step comes first.
      const auto straighter = [&](int q, int r) {
        const int turn = compare_turn(A, B, P(v), P(q), P(r));
        return turn < 0 || (turn == 0 && nearer(q, r));
      };
      std::vector<int> order;
      auto take = [&](auto&& qualifies, auto&& before) {
        std::vector<int> pool;
        for (int w : ahead_of_v)
          if (qualifies(w) && std::find(order.begin(), order.end(), w) == order.end()) pool.push_back(w);
        std::sort(pool.begin(), pool.end(), before);
        order.insert(order.end(), pool.begin(), pool.end());
      };
      for (double tol : tiers) take([&](int w) { return listed(w) && within(A, B, P(w), tol); }, straighter);
      take([&](int w) { return listed(w) && near_line(A, B, P(w)); }, nearer);
      for (double tol : tiers) take([&](int w) { return within(A, B, P(w), tol); }, nearer);
      return order;
    };
    std::vector<int> chain{a};
    std::vector<std::vector<int>> options{steps(a)};
    std::vector<std::size_t> tried{0};
    std::unordered_set<int> dead;
    int stuck = -1;
    // B ends the chain at once when a listed edge joins it, or any edge where no
    // listed step leads on; else after the listed steps: a split whose rounded
    // point lies off its line may keep the triangle beside its sliver (ALGORITHM.md
    // section 6), so the last chain vertex before B is joined to B by an unlisted
    // edge too, the sliver's base, and the chain goes round through the point.
    const auto listed_step = [&](int v, const std::vector<int>& next) {
      return std::any_of(next.begin(), next.end(), [&](int w) { return listed_.count(edge_key(v, w)) != 0; });
    };
    while (!chain.empty()) {
      const int v = chain.back();
      const bool joined = adjacent(v, b);
      if (joined && (listed_.count(edge_key(v, b)) != 0 || !listed_step(v, options.back()) ||
                     tried.back() == options.back().size())) {
        chain.push_back(b);
        return chain;
      }
      if (tried.back() == options.back().size()) {  // nothing ahead of here reaches B
        if (stuck < 0) stuck = chain.back();
        dead.insert(chain.back());
        chain.pop_back(), options.pop_back(), tried.pop_back();
        continue;
      }
      const int w = options.back()[tried.back()++];
      if (dead.count(w)) continue;
      chain.push_back(w);
      options.push_back(steps(w));
      tried.push_back(0);
    }
    return {-1, stuck};
  }

  // Where validate() split a file's segment (at a vertex on it, or with
  // --split-crossings at a crossing rounded to doubles), the pieces must stay
  // on that segment: each joint within the chain tolerance of the line through
  // the segment's ends (segment_tolerance with the joints as interior
  // vertices). A rounded crossing is within half an ulp per coordinate.
  void check_split_points() {
    const std::vector<int>& origin = pslg_.segment_origin;
    if (origin.size() != pslg_.segments.size()) return;
    for (std::size_t first = 0; first < origin.size();) {
      std::size_t last = first;
      while (last + 1 < origin.size() && origin[last + 1] == origin[first]) ++last;
      if (last > first) {
        const int a = input_to_mesh_[static_cast<std::size_t>(pslg_.segments[first].a)];
        const int b = input_to_mesh_[static_cast<std::size_t>(pslg_.segments[last].b)];
        if (a >= 0 && b >= 0) {
          const double tol = segment_tolerance(P(a), P(b), last - first);
          for (std::size_t k = first; k < last; ++k) {
            const int v = input_to_mesh_[static_cast<std::size_t>(pslg_.segments[k].b)];
            if (v < 0 || within(P(a), P(b), P(v), tol)) continue;
            add({Reason::SteinerOffSegment,
                 fmt::format("vertex {} {} where segment {} of the input was split is off it ({} {}) by more than the "
                             "tolerance {} per coordinate",
                             v, pt(P(v)), origin[first] + 1, pt(P(a)), pt(P(b)), tol),
                 {}, {}, {v, a, b}, {}, static_cast<int>(k)});
          }
        }
      }
      first = last + 1;
    }
  }

  void find_chains() {
    chains_.assign(pslg_.segments.size(), {});
    vertex_segment_.assign(mesh_.vertices.size(), -1);
    constrained_half_.assign(mesh_.triangles.size() * 3, 0);
    for (std::size_t s = 0; s < pslg_.segments.size(); ++s) {
      const int a = input_to_mesh_[static_cast<std::size_t>(pslg_.segments[s].a)];
      const int b = input_to_mesh_[static_cast<std::size_t>(pslg_.segments[s].b)];
      const bool in_domain = domain_.segment_sides[s] != 0;
      if (a < 0 || b < 0 || !used_[static_cast<std::size_t>(a)] || !used_[static_cast<std::size_t>(b)]) {
        if (in_domain)
          add({Reason::SegmentMissing, fmt::format("segment {} ({}-{}): an endpoint is not in the mesh", s, pslg_.segments[s].a, pslg_.segments[s].b),
               {}, {}, {}, {}, static_cast<int>(s)});
        continue;
      }
      std::vector<int> chain = walk(a, b);
      if (chain.front() == -1) {
        const int stuck = chain.back();
        if (in_domain)
          add({Reason::SegmentMissing,
               fmt::format("segment {} {}-{} {} {} is not a chain of mesh edges: no edge continues it from vertex {} {}", s, a, b,
                           pt(P(a)), pt(P(b)), stuck, pt(P(stuck))),
               {}, {}, {a, b, stuck}, {}, static_cast<int>(s)});
        continue;
      }
      const std::size_t interior = chain.size() - 2;
      const double tol = segment_tolerance(P(a), P(b), interior);
      for (std::size_t k = 1; k + 1 < chain.size(); ++k) {
        const int v = chain[k];
        if (!within(P(a), P(b), P(v), tol))
          add({Reason::SteinerOffSegment,
               fmt::format("vertex {} {} of segment {} {}-{} {} {} is off the segment by more than the tolerance {} per coordinate", v,
                           pt(P(v)), s, a, b, pt(P(a)), pt(P(b)), tol),
               {}, {}, {v, a, b}, {}, static_cast<int>(s)});
        vertex_segment_[static_cast<std::size_t>(v)] = static_cast<int>(s);  // a Steiner point: the walk takes no input vertex
      }
      for (std::size_t k = 0; k + 1 < chain.size(); ++k) chain_edge_[edge_key(chain[k], chain[k + 1])] = static_cast<int>(s);
      chains_[s] = std::move(chain);
    }
    for (std::size_t h = 0; h < constrained_half_.size(); ++h)
      if (tri_ok_[h / 3] && chain_edge_.count(edge_key(from(static_cast<int>(h)), to(static_cast<int>(h))))) constrained_half_[h] = 1;
    report_.stats.constrained_edges = chain_edge_.size();
    // Sorted: the checks and reports that scan them do not depend on the hash's order.
    std::vector<std::pair<std::uint64_t, int>> keyed(chain_edge_.begin(), chain_edge_.end());
    std::sort(keyed.begin(), keyed.end());
    for (const auto& [key, seg] : keyed) {
      const std::array<int, 2> e = edge_ends(key);
      chain_edges_.push_back(e);
      chain_edge_segment_.push_back(seg);
      chain_segments_.segments.push_back({P(e[0]), P(e[1])});
    }
  }

  void check_listed_constrained_edges() {
    for (const ConstrainedEdge& e : mesh_.constrained_edges) {
      auto it = chain_edge_.find(edge_key(e.a, e.b));
      const bool ids = e.a >= 0 && e.b >= 0 && static_cast<std::size_t>(e.a) < mesh_.vertices.size() &&
                       static_cast<std::size_t>(e.b) < mesh_.vertices.size();
      if (it == chain_edge_.end()) {
        add({Reason::ConstrainedEdgeNotOnSegment,
             ids ? fmt::format("listed constrained edge {}-{} {} {} is on no input segment's chain", e.a, e.b, pt(P(e.a)), pt(P(e.b)))
                 : fmt::format("listed constrained edge {}-{} has a vertex id out of range", e.a, e.b),
             {}, {{e.a, e.b}}, ids ? std::vector<int>{e.a, e.b} : std::vector<int>{}, {}, e.segment});
      } else if (e.segment >= 0 && e.segment != it->second) {
        add({Reason::ConstrainedEdgeWrongSegment,
             fmt::format("constrained edge {}-{} is tagged segment {} but lies on segment {}", e.a, e.b, e.segment, it->second), {},
             {{e.a, e.b}}, {e.a, e.b}, {}, it->second});
      }
    }
    if (mesh_.constrained_edges.empty()) return;  // the mesh lists none: found by geometry only
    for (const auto& [key, s] : chain_edge_)
      if (!listed_.count(key)) {
        const auto [a, b] = edge_ends(key);
        add({Reason::ConstrainedEdgeUnlisted,
             fmt::format("edge {}-{} {} {} lies on segment {} but the mesh does not list it as constrained", a, b, pt(P(a)), pt(P(b)), s),
             {}, {{a, b}}, {a, b}, {}, s});
      }
  }

  // Coverage: with every triangle CCW and every interior edge used once each way,
  // the number of triangles over a point is the winding number of the mesh's
  // boundary edges; these checks make that boundary the domain's (docs/CERTIFIER.md).
  void check_coverage() {
    std::unordered_map<std::uint64_t, std::array<int, 2>> halves_of_chain;  // chain edge -> (half a->b, half b->a)
    for (std::size_t h = 0; h < twin_.size(); ++h) {
      if (!tri_ok_[h / 3]) continue;
      const int x = from(static_cast<int>(h)), y = to(static_cast<int>(h));
      auto it = chain_edge_.find(edge_key(x, y));
      if (it == chain_edge_.end()) {
        if (twin_[h] == -1)
          add({Reason::BoundaryNotOnDomainBoundary,
               fmt::format("edge {}-{} {} {} of {} has no triangle on its other side but lies on no segment (a gap)", x, y, pt(P(x)),
                           pt(P(y)), tri_text(h / 3)),
               {static_cast<int>(h / 3)}, {{x, y}}, {x, y}, {}, -1});
        continue;
      }
      auto& pair = halves_of_chain.try_emplace(it->first, std::array<int, 2>{-1, -1}).first->second;
      pair[x < y ? 0 : 1] = static_cast<int>(h);
    }
    for (std::size_t s = 0; s < chains_.size(); ++s) {
      const std::vector<int>& chain = chains_[s];
      const unsigned char sides = domain_.segment_sides[s];
      for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
        const int u = chain[k], w = chain[k + 1];
        auto it = halves_of_chain.find(edge_key(u, w));
        const std::array<int, 2> pair = it == halves_of_chain.end() ? std::array<int, 2>{-1, -1} : it->second;
        const int left = pair[u < w ? 0 : 1], right = pair[u < w ? 1 : 0];  // half u->w has its triangle on the left
        auto side = [&](int half, bool domain, const char* name) {
          if (domain && half < 0)
            add({Reason::DomainBoundaryUncovered,
                 fmt::format("no triangle on the {} of edge {}-{} {} {} of segment {}, a domain side (a gap)", name, u, w, pt(P(u)),
                             pt(P(w)), s),
                 {}, {{u, w}}, {u, w}, {}, static_cast<int>(s)});
          if (!domain && half >= 0)
            add({Reason::MeshOutsideDomain,
                 fmt::format("{} lies on the {} of segment {} edge {}-{}, outside the domain (exterior or hole)", tri_text(half / 3), name,
                             s, u, w),
                 {half / 3}, {{u, w}}, {u, w}, {}, static_cast<int>(s)});
        };
        side(left, sides & ExpectedDomain::Left, "left");
        side(right, sides & ExpectedDomain::Right, "right");
      }
    }
  }

  // The coverage checks above count triangles by the chains' winding number,
  // the domain's only where the chains are drawn as the segments are: no two
  // chain edges meet but at a shared endpoint, no mesh vertex lies on one
  // (chain_embedding.h). Chains within the tolerance of nearly parallel
  // segments can cross where the segments do not.
  void check_chains_cross_nowhere() {
    const std::vector<std::array<int, 2>>& edges = chain_edges_;
    std::vector<ChainMeet> meets = chain_meetings(mesh_.vertices, edges, used_);
    std::sort(meets.begin(), meets.end(), [](const ChainMeet& x, const ChainMeet& y) {
      return std::tie(x.edge, x.other, x.vertex) < std::tie(y.edge, y.other, y.vertex);
    });
    auto text = [&](int i) {
      const auto& e = edges[static_cast<std::size_t>(i)];
      return fmt::format("edge {}-{} {} {} of segment {}", e[0], e[1], pt(P(e[0])), pt(P(e[1])), chain_edge_segment_[static_cast<std::size_t>(i)]);
    };
    for (const ChainMeet& m : meets) {
      const auto& e = edges[static_cast<std::size_t>(m.edge)];
      const int s = chain_edge_segment_[static_cast<std::size_t>(m.edge)];
      if (m.other >= 0) {
        const auto& f = edges[static_cast<std::size_t>(m.other)];
        add({Reason::ChainEdgesMeet,
             fmt::format("{} and {} meet other than at a shared end: the mesh's boundary crosses itself, so it covers part of the "
                         "plane twice or leaves out domain (a point placed across a nearly parallel segment?)",
                         text(m.edge), text(m.other)),
             {}, {e, f}, {e[0], e[1], f[0], f[1]}, {}, s});
      } else {
        add({Reason::ChainEdgesMeet,
             fmt::format("mesh vertex {} {} lies on {} but is not one of its ends: its triangles overlap the ones along that edge",
                         m.vertex, pt(P(m.vertex)), text(m.edge)),
             {}, {e}, {m.vertex, e[0], e[1]}, {}, s});
      }
    }
  }

  void check_euler() {
    long v = 0;
    for (char u : used_) v += u;
    std::size_t f = 0;
    for (char ok : tri_ok_) f += ok;
    const long euler = v - static_cast<long>(edges_.size()) + static_cast<long>(f);
    report_.stats.euler_mesh = euler;
    report_.stats.euler_domain = domain_.euler;
    if (euler != domain_.euler)
      add({Reason::EulerCharacteristic,
           fmt::format("V - E + F = {} - {} + {} = {}, the domain's is {}", v, edges_.size(), f, euler, domain_.euler), {}, {}, {}, {}, -1});
  }

  // --- 4. Delaunay ------------------------------------------------------------
  void check_delaunay() {
    for (std::size_t h = 0; h < twin_.size(); ++h) {
      const int g = twin_[h];
      if (g < static_cast<int>(h)) continue;  // each interior edge once; boundary and bad edges skipped
      if (constrained_half_[h] && !opt_.conforming) continue;
      const int a = from(static_cast<int>(h)), b = to(static_cast<int>(h)), c = apex(static_cast<int>(h)), d = apex(g);
      ++report_.stats.delaunay_edges_checked;
      if (exact::orient(P(a), P(b), P(c)) <= 0) continue;  // reported; in-circle meaningless
      const int side = exact::incircle(P(a), P(b), P(c), P(d));
      if (side == 0) ++report_.stats.cocircular_edges;
      if (side > 0)
        add({Reason::NotLocallyDelaunay,
             fmt::format("{}edge {}-{} {} {} is not locally Delaunay: vertex {} {} is strictly inside the circumcircle of {}",
                         constrained_half_[h] ? "constrained " : "", a, b, pt(P(a)), pt(P(b)), d, pt(P(d)), tri_text(h / 3)),
             {static_cast<int>(h / 3), g / 3}, {{a, b}}, {a, b, c, d}, {}, -1});
    }
  }

  // --- 5. Minimum angle ---------------------------------------------------
  // Edge order (ALGORITHM.md section 3): (squared length, -min id, -max id); true iff e > f.
  bool longer(int a, int b, int c, int d) const {
    const int s = exact::compare_squared_length(P(a), P(b), P(c), P(d));
    if (s != 0) return s > 0;
    const int e0 = std::min(a, b), e1 = std::max(a, b), f0 = std::min(c, d), f1 = std::max(c, d);
    return e0 != f0 ? e0 < f0 : e1 < f1;
  }

  void compute_longest_edges() {
    longest_.assign(mesh_.triangles.size(), 0);
    for (std::size_t t = 0; t < mesh_.triangles.size(); ++t) {
      if (!tri_ok_[t]) continue;
      int best = 0;
      for (int i = 1; i < 3; ++i) {
        const int h = static_cast<int>(3 * t) + i, b = static_cast<int>(3 * t) + best;
        if (longer(from(h), to(h), from(b), to(b))) best = i;
      }
      longest_[t] = static_cast<signed char>(best);
    }
  }

  std::vector<int> segments_of(int v) const {
    std::vector<int> out;
    const int in = mesh_to_input_[static_cast<std::size_t>(v)];
    if (in >= 0) {
      for (std::size_t s = 0; s < pslg_.segments.size(); ++s)
        if (pslg_.segments[s].a == in || pslg_.segments[s].b == in) out.push_back(static_cast<int>(s));
    } else if (vertex_segment_[static_cast<std::size_t>(v)] >= 0) {
      out.push_back(vertex_segment_[static_cast<std::size_t>(v)]);
    }
    return out;
  }

  // ALGORITHM.md section 8, checked on the mesh itself.
  bool unimprovable_rule_holds(std::size_t t, double s_hi) const {
    const int shortest_half = [&] {
      int best = 0;
      for (int i = 1; i < 3; ++i) {
        const int h = static_cast<int>(3 * t) + i, b = static_cast<int>(3 * t) + best;
        if (longer(from(b), to(b), from(h), to(h))) best = i;
      }
      return static_cast<int>(3 * t) + best;
    }();
    const int p = from(shortest_half), q = to(shortest_half);
    const int r = T(t)[static_cast<std::size_t>((shortest_half % 3 + 2) % 3)];
    for (int s1 : segments_of(p))
      for (int s2 : segments_of(q)) {
        if (s1 == s2) continue;
        const Segment &x = pslg_.segments[static_cast<std::size_t>(s1)], &y = pslg_.segments[static_cast<std::size_t>(s2)];
        for (int v_in : {x.a, x.b}) {
          if (v_in != y.a && v_in != y.b) continue;
          const int v = input_to_mesh_[static_cast<std::size_t>(v_in)];
          if (v < 0 || v == p || v == q) continue;
          const Point& V = pslg_.vertices[static_cast<std::size_t>(v_in)];
          const Point& U = pslg_.vertices[static_cast<std::size_t>(x.a == v_in ? x.b : x.a)];
          const Point& W = pslg_.vertices[static_cast<std::size_t>(y.a == v_in ? y.b : y.a)];
          // Inside the wedge: the third vertex on s1 or s2, or in the closed sector at v between them.
          const std::vector<int> on = segments_of(r);
          if (std::find(on.begin(), on.end(), s1) == on.end() && std::find(on.begin(), on.end(), s2) == on.end()) {
            const int sigma = exact::orient(V, U, W);
            if (exact::orient(V, U, P(r)) * sigma < 0 || exact::orient(V, P(r), W) * sigma < 0) continue;
          }
          if (exact::acute_angle_sin2_below(V, U, W, s_hi)) return true;
        }
      }
    return false;
  }

  // --- The small-input-angle exemption rule (docs/CERTIFIER.md) --------------
  // Mesh vertex p is on segment s of angle a ("an arm"): s's other endpoint, or a vertex
  // of s's chain (the apex itself excluded).
  bool on_arm(int p, int s, int end) const {
    const int in = mesh_to_input_[static_cast<std::size_t>(p)];
    if (in >= 0) return in == end;
    return vertex_segment_[static_cast<std::size_t>(p)] == s;
  }
  // |p - apex| <= R (the shorter segment's length), exactly.
  bool in_disk(int p, const SmallInputAngle& a) const {
    const Point& V = pslg_.vertices[static_cast<std::size_t>(a.apex)];
    const Point& X = P(p);
    if (std::abs(X.x - V.x) > 2 * a.radius || std::abs(X.y - V.y) > 2 * a.radius) return false;  // far: cheap
    return exact::compare_squared_length(V, X, V, pslg_.vertices[static_cast<std::size_t>(a.near_end)]) <= 0;
  }
  // Triangle pqr, pq joining the two arms of a, lies in the wedge: r is on an arm (or is
  // the apex), or in the closed sector from segment1 counter-clockwise to segment2 (exact).
  bool inside_wedge(int r, const SmallInputAngle& a) const {
    if (on_arm(r, a.segment1, a.end1) || on_arm(r, a.segment2, a.end2)) return true;
    const Point& V = pslg_.vertices[static_cast<std::size_t>(a.apex)];
    const Point &E1 = pslg_.vertices[static_cast<std::size_t>(a.end1)], &E2 = pslg_.vertices[static_cast<std::size_t>(a.end2)];
    return exact::orient(V, E1, P(r)) >= 0 && exact::orient(V, P(r), E2) >= 0;
  }
  // The first small input angle (Report::small_angles order) that exempts triangle t, or -1.
  // Every shortest edge is tried (exact ties kept), so the answer does not depend on the
  // mesh's vertex numbering. Exempt iff, for some angle a and some shortest edge pq:
  //  span: p is on one arm of a and q on the other (the edge crosses the wedge) and the
  //        triangle lies in the wedge (its third vertex on an arm or in the sector), or
  //  near: p and q lie in the disk of a (within the shorter segment's length of the apex).
  int exempting_angle(std::size_t t) const {
    const Tri& x = T(t);
    std::array<std::array<int, 3>, 3> shortest{};  // p, q, and the third vertex
    int count = 0;
    for (int i = 0; i < 3; ++i) {
      const int p = x[static_cast<std::size_t>(i)], q = x[static_cast<std::size_t>((i + 1) % 3)];
      bool is_shortest = true;
      for (int j = 0; j < 3 && is_shortest; ++j)
        if (j != i)
          is_shortest = exact::compare_squared_length(P(p), P(q), P(x[static_cast<std::size_t>(j)]),
                                                      P(x[static_cast<std::size_t>((j + 1) % 3)])) <= 0;
      if (is_shortest) shortest[static_cast<std::size_t>(count++)] = {p, q, x[static_cast<std::size_t>((i + 2) % 3)]};
    }
    const auto& angles = report_.small_angles;
    for (std::size_t k = 0; k < angles.size(); ++k) {
      const SmallInputAngle& a = angles[k];
      for (int e = 0; e < count; ++e) {
        const int p = shortest[static_cast<std::size_t>(e)][0], q = shortest[static_cast<std::size_t>(e)][1];
        const int r = shortest[static_cast<std::size_t>(e)][2];
        const bool span = (on_arm(p, a.segment1, a.end1) && on_arm(q, a.segment2, a.end2)) ||
                          (on_arm(p, a.segment2, a.end2) && on_arm(q, a.segment1, a.end1));
        if (span && inside_wedge(r, a)) return static_cast<int>(k);
        if (in_disk(p, a) && in_disk(q, a)) return static_cast<int>(k);
      }
    }
    return -1;
  }

  void check_angles() {
    const Sin2Bracket bracket = sin2_bracket(opt_.min_angle_deg);
    auto sorted = [](Tri x) {
      std::sort(x.begin(), x.end());
      return x;
    };
    std::map<Tri, std::size_t> listed;  // sorted triple -> index in options.unimprovable
    for (std::size_t i = 0; i < opt_.unimprovable.size(); ++i) listed.emplace(sorted(opt_.unimprovable[i].triangle), i);
    std::vector<char> found(opt_.unimprovable.size(), 0);
    for (std::size_t t = 0; t < mesh_.triangles.size(); ++t) {
      if (!tri_ok_[t]) continue;
      const Tri& x = T(t);
      int worst = -1;  // corner with an angle below theta (the smallest such angle is not needed)
      bool certainly = false;
      for (int i = 0; i < 3; ++i) {
        const Point &o = P(x[static_cast<std::size_t>(i)]), &p = P(x[static_cast<std::size_t>((i + 1) % 3)]),
                    &q = P(x[static_cast<std::size_t>((i + 2) % 3)]);
        if (exact::acute_angle_sin2_below(o, p, q, bracket.hi)) {
          const bool below = exact::acute_angle_sin2_below(o, p, q, bracket.lo);
          if (worst < 0 || (below && !certainly)) {
            worst = i;
            certainly = below;
          }
        }
      }
      if (worst < 0) continue;
      // Decided before the engine's list is looked at: the rule sees only input and mesh.
      const int exempt = opt_.exempt_small_input_angles ? exempting_angle(t) : -1;
      if (exempt >= 0) {
        report_.exempt_triangles.push_back(static_cast<int>(t));
        report_.exempt_angle.push_back(exempt);
      }
      // The precision limit (section 5c), likewise from input and mesh alone.
      std::optional<PrecisionVerdict> searched;  // kept for a listed claim below: the search is not run twice
      if (exempt < 0 && opt_.exempt_precision_limited)
        searched = precision_verdict(precision_view(), t, opt_.precision_method, opt_.precision_ties_by_ids);
      const bool limited = searched == PrecisionVerdict::Limited;
      if (limited) report_.precision_exempt_triangles.push_back(static_cast<int>(t));
      auto it = listed.find(sorted(x));
      if (it != listed.end()) {
        const std::size_t listed_index = it->second;
        found[listed_index] = 1;
        if (opt_.unimprovable[listed_index].reason == LeftReason::DoublePrecision) {
          const PrecisionVerdict verdict =
              searched ? *searched : precision_verdict(precision_view(), t, opt_.precision_method, opt_.precision_ties_by_ids);
          if (verdict == PrecisionVerdict::Limited) {
            report_.unimprovable_accepted.push_back(opt_.unimprovable[listed_index]);
            continue;
          }
          // Undecided: the claim cannot be verified, so it is not accepted; the text says which.
          if (verdict == PrecisionVerdict::Undecided) ++report_.precision_undecided;
          add({Reason::UnimprovableRuleFails,
               verdict == PrecisionVerdict::Insertable
                   ? fmt::format("{} is listed as limited by double precision but a point Select Point ({}) allows for it, as "
                                 "rounded, can be inserted",
                                 tri_text(t), to_string(opt_.precision_method))
                   : fmt::format("{} is listed as limited by double precision but the search of its Lepps under every "
                                 "resolution of exact length ties stopped undecided (more than {} Lepp states, or a bad "
                                 "triangle), so the claim is not verified",
                                 tri_text(t), kTieSearchStates),
               {static_cast<int>(t)}, {}, {x[0], x[1], x[2]}, {}, -1});
          continue;
        }
        if (unimprovable_rule_holds(t, bracket.hi)) {
          report_.unimprovable_accepted.push_back(opt_.unimprovable[listed_index]);
          continue;
        }
        add({Reason::UnimprovableRuleFails,
             fmt::format("{} is listed unimprovable but its shortest edge does not join two segments meeting at an input angle below {}",
                         tri_text(t), opt_.min_angle_deg),
             {static_cast<int>(t)}, {}, {x[0], x[1], x[2]}, {}, -1});
        continue;
      }
      if (exempt >= 0 || limited) continue;
      const double deg = min_angle_deg(P(x[0]), P(x[1]), P(x[2]));
      add({certainly ? Reason::AngleBelowTheta : Reason::AngleNotCertified,
           fmt::format("{} has an angle at vertex {} {} theta = {} (about {} degrees)", tri_text(t), x[static_cast<std::size_t>(worst)],
                       certainly ? "below" : "within one ulp of", opt_.min_angle_deg, deg),
           {static_cast<int>(t)}, {}, {x[0], x[1], x[2]}, {}, -1});
    }
    report_.exempt_count = report_.exempt_triangles.size();
    report_.precision_exempt_count = report_.precision_exempt_triangles.size();
    // Listed but not skinny is harmless for the angle check; listed but absent is not.
    std::set<Tri> triangles;
    if (std::find(found.begin(), found.end(), 0) != found.end())
      for (std::size_t t = 0; t < mesh_.triangles.size(); ++t) triangles.insert(sorted(T(t)));
    for (std::size_t i = 0; i < opt_.unimprovable.size(); ++i) {
      const Tri& x = opt_.unimprovable[i].triangle;
      if (!found[i] && !triangles.count(sorted(x)))
        add({Reason::UnimprovableNotInMesh,
             fmt::format("listed unimprovable triangle {} {} {} is not a triangle of the mesh", x[0], x[1], x[2]), {}, {}, {}, {}, -1});
    }
  }

  PrecisionView precision_view() const { return {mesh_, tri_ok_, twin_, constrained_half_, outside_, chain_segments_}; }
  // The input outside the expected domain: vertices on no domain triangle, segments
  // with the domain on neither side (the precision exemption's sliver clause).
  void collect_outside_input() {
    for (std::size_t i = 0; i < pslg_.vertices.size(); ++i)
      if (!domain_.vertex_in_domain[i]) outside_.vertices.push_back(pslg_.vertices[i]);
    for (std::size_t s = 0; s < pslg_.segments.size(); ++s)
      if (domain_.segment_sides[s] == 0)
        outside_.segments.push_back({pslg_.vertices[static_cast<std::size_t>(pslg_.segments[s].a)],
                                     pslg_.vertices[static_cast<std::size_t>(pslg_.segments[s].b)]});
  }

  // --- 6. Theorem 2 and the Lepp statistic -----------------------------------
  int longest_half(std::size_t t) const { return static_cast<int>(3 * t) + longest_[t]; }

  void check_theorem2() {
    for (std::size_t t = 0; t < mesh_.triangles.size(); ++t) {
      if (!tri_ok_[t]) continue;
      const int h = longest_half(t), g = twin_[static_cast<std::size_t>(h)];
      if (g < h || constrained_half_[static_cast<std::size_t>(h)]) continue;  // once per pair; boundary, bad, constrained skipped
      if (longest_half(static_cast<std::size_t>(g / 3)) != g) continue;       // not terminal
      ++report_.stats.terminal_pairs_checked;
      const int a = from(h), b = to(h);
      for (int half : {h, g}) {
        const int c = apex(half);
        if (exact::angle_over_120(P(c), P(a), P(b))) {
          const Point &C = P(c), &A = P(a), &B = P(b);
          const double deg = angle_deg(C, A, B);  // scaled: right at 1e299 and 1e-301 too
          add({Reason::TerminalAngleOver120,
               fmt::format("terminal edge {}-{} {} {} (triangles {} and {}): the angle at {} {} is over 120 degrees (about {})", a, b,
                           pt(A), pt(B), h / 3, g / 3, c, pt(C), deg),
               {h / 3, g / 3}, {{a, b}}, {a, b, c}, {}, -1});
        }
      }
    }
  }

  // --- 7. Size bounds -----------------------------------------------------------
  // The lowest-index CCW triangle whose closed interior holds q, and how many of its
  // edges q lies on; triangle -1 when none holds it (a gap, reported elsewhere).
  struct Location {
    int triangle = -1;
    int zeros = 0;    // 0 strictly inside, 1 on an edge, 2 at a vertex
    int corner = -1;  // on an edge: its half-edge index i (T[i] -> T[i+1]); at a vertex: the vertex's index i
  };
  Location locate(const Point& q) const {
    for (std::size_t t = 0; t < mesh_.triangles.size(); ++t) {
      if (!tri_ok_[t]) continue;
      const Tri& x = T(t);
      const Point &a = P(x[0]), &b = P(x[1]), &c = P(x[2]);
      if (q.x < std::min({a.x, b.x, c.x}) || q.x > std::max({a.x, b.x, c.x}) || q.y < std::min({a.y, b.y, c.y}) ||
          q.y > std::max({a.y, b.y, c.y}))
        continue;
      if (exact::orient(a, b, c) <= 0) continue;
      std::array<int, 3> o{};
      bool inside = true;
      for (int i = 0; i < 3 && inside; ++i) {
        o[static_cast<std::size_t>(i)] = exact::orient(P(x[static_cast<std::size_t>(i)]), P(x[static_cast<std::size_t>((i + 1) % 3)]), q);
        inside = o[static_cast<std::size_t>(i)] >= 0;
      }
      if (!inside) continue;
      Location l{static_cast<int>(t), 0, -1};
      for (int i = 0; i < 3; ++i)
        if (o[static_cast<std::size_t>(i)] == 0) ++l.zeros;
      if (l.zeros == 1) {
        for (int i = 0; i < 3; ++i)
          if (o[static_cast<std::size_t>(i)] == 0) l.corner = i;
      } else if (l.zeros == 2) {
        // Edges i and i+1 meet at vertex i+1 (edge i runs T[i] -> T[i+1]).
        for (int i = 0; i < 3; ++i)
          if (o[static_cast<std::size_t>(i)] == 0 && o[static_cast<std::size_t>((i + 1) % 3)] == 0) l.corner = (i + 1) % 3;
      }
      return l;
    }
    return {};
  }

  // The half-edge x -> y of a valid triangle, or -1.
  int half_edge(int x, int y) const {
    for (std::size_t h = 0; h < twin_.size(); ++h)
      if (tri_ok_[h / 3] && from(static_cast<int>(h)) == x && to(static_cast<int>(h)) == y) return static_cast<int>(h);
    return -1;
  }

  // A region point the mesh puts on a chain of segment s (at its vertex v, or on its
  // edge from chain[k] to chain[k + 1]) while the input has it off the segment (a chain
  // vertex rounded off the line): the triangle on the point's side of the segment.
  int seed_beside_chain(int s, std::size_t k, const Point& q) const {
    const Segment& seg = pslg_.segments[static_cast<std::size_t>(s)];
    const int side = exact::orient(pslg_.vertices[static_cast<std::size_t>(seg.a)], pslg_.vertices[static_cast<std::size_t>(seg.b)], q);
    const std::vector<int>& chain = chains_[static_cast<std::size_t>(s)];
    if (side == 0 || k + 1 >= chain.size()) return -1;
    // Half-edge x -> y has its triangle on its left: the left side of a -> b.
    const int h = side > 0 ? half_edge(chain[k], chain[k + 1]) : half_edge(chain[k + 1], chain[k]);
    return h < 0 ? -1 : h / 3;
  }

  // The triangles a region point floods from (docs/CERTIFIER.md section 7).
  std::vector<int> region_seeds(const Point& q) const {
    const Location l = locate(q);
    if (l.triangle < 0) return {};
    const Tri& x = T(static_cast<std::size_t>(l.triangle));
    if (l.zeros == 1) {
      const int a = x[static_cast<std::size_t>(l.corner)], b = x[static_cast<std::size_t>((l.corner + 1) % 3)];
      auto it = chain_edge_.find(edge_key(a, b));
      if (it == chain_edge_.end()) return {l.triangle};  // an unconstrained edge: the flood crosses it
      const std::vector<int>& chain = chains_[static_cast<std::size_t>(it->second)];
      for (std::size_t k = 0; k + 1 < chain.size(); ++k)
        if (edge_key(chain[k], chain[k + 1]) == it->first) {
          const int seed = seed_beside_chain(it->second, k, q);
          return seed < 0 ? std::vector<int>{} : std::vector<int>{seed};
        }
      return {};
    }
    if (l.zeros == 2) {
      const int v = x[static_cast<std::size_t>(l.corner)];
      if (mesh_to_input_[static_cast<std::size_t>(v)] >= 0) return {};  // an input vertex: nothing (and see InputVertexMoved)
      const int s = vertex_segment_[static_cast<std::size_t>(v)];
      if (s >= 0) {
        const std::vector<int>& chain = chains_[static_cast<std::size_t>(s)];
        const std::size_t k = static_cast<std::size_t>(std::find(chain.begin(), chain.end(), v) - chain.begin());
        const int seed = seed_beside_chain(s, k, q);
        return seed < 0 ? std::vector<int>{} : std::vector<int>{seed};
      }
      std::vector<int> fan;  // a Steiner vertex off every segment: its triangles, one region
      for (std::size_t t = 0; t < mesh_.triangles.size(); ++t)
        if (tri_ok_[t] && (T(t)[0] == v || T(t)[1] == v || T(t)[2] == v)) fan.push_back(static_cast<int>(t));
      return fan;
    }
    return {l.triangle};
  }

  // Each region point, in file order, floods the mesh across edges on no segment chain,
  // overwriting earlier regions (Triangle's order, ALGORITHM.md section 2).
  void assign_regions() {
    const std::size_t n = pslg_.regions.size();
    report_.region_places = domain_.region_places;
    report_.triangle_region.assign(mesh_.triangles.size(), -1);
    std::vector<int> stamp(mesh_.triangles.size(), -1);
    for (std::size_t r = 0; r < n; ++r) {
      if (domain_.region_places[r] != RegionPlace::Floods) continue;
      std::vector<int> todo = region_seeds(pslg_.regions[r].at);
      for (int t : todo) stamp[static_cast<std::size_t>(t)] = static_cast<int>(r);
      while (!todo.empty()) {
        const int t = todo.back();
        todo.pop_back();
        report_.triangle_region[static_cast<std::size_t>(t)] = static_cast<int>(r);
        for (int i = 0; i < 3; ++i) {
          const std::size_t h = static_cast<std::size_t>(3 * t + i);
          const int g = twin_[h];
          if (g < 0 || constrained_half_[h] || stamp[static_cast<std::size_t>(g / 3)] == static_cast<int>(r)) continue;
          stamp[static_cast<std::size_t>(g / 3)] = static_cast<int>(r);
          todo.push_back(g / 3);
        }
      }
    }
    report_.region_triangles.assign(n, 0);
    for (int r : report_.triangle_region)
      if (r >= 0) ++report_.region_triangles[static_cast<std::size_t>(r)];
  }

  static bool is_bound(double b) { return b > 0 && std::isfinite(b); }

  // |orient(a, b, c)| > 2 * bound, exactly: the doubled area against twice the bound.
  static bool area_above(const Point& a, const Point& b, const Point& c, double bound) {
    return exact::sign([&](auto z) -> decltype(z) {
             using NT = decltype(z);
             NT det = (NT(b.x) - NT(a.x)) * (NT(c.y) - NT(a.y)) - (NT(b.y) - NT(a.y)) * (NT(c.x) - NT(a.x));
             return CGAL::abs(det) - (NT(bound) + NT(bound));
           }) > 0;
  }

  std::string region_text(int r) const {
    const std::size_t i = static_cast<std::size_t>(r);
    const int line = i < pslg_.region_lines.size() ? pslg_.region_lines[i] : 0;
    return line > 0 ? fmt::format("region {} (line {} of {})", r, line, pslg_.source.empty() ? "the input" : pslg_.source)
                    : fmt::format("region {}", r);
  }

  void check_area_bounds() {
    report_.max_area = is_bound(opt_.max_area) ? opt_.max_area : 0;
    report_.region_area_bounds = opt_.region_area_bounds;
    for (std::size_t t = 0; t < mesh_.triangles.size(); ++t) {
      if (!tri_ok_[t]) continue;
      const int r = opt_.region_area_bounds ? report_.triangle_region[t] : -1;
      const double regional = r >= 0 ? pslg_.regions[static_cast<std::size_t>(r)].max_area : 0;
      // The smaller bound applies; on a tie, the region's is named.
      const bool use_region = is_bound(regional) && (report_.max_area <= 0 || regional <= report_.max_area);
      const double bound = use_region ? regional : report_.max_area;
      if (bound <= 0) continue;
      ++report_.area_checked;
      const Tri& x = T(t);
      if (!area_above(P(x[0]), P(x[1]), P(x[2]), bound)) continue;
      const Point &a = P(x[0]), &b = P(x[1]), &c = P(x[2]);
      const double area = std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) / 2;
      const std::string whose = use_region ? fmt::format("the bound {} of {}", bound, region_text(r))
                                           : fmt::format("the global bound {} (--max-area){}", bound,
                                                         r >= 0 ? ", in " + region_text(r)
                                                         : opt_.region_area_bounds ? std::string(", in no region") : std::string());
      Violation v{Reason::AreaAboveBound,
                  fmt::format("{} has area about {}, above {} (exactly: doubled area > 2 x bound)", tri_text(t), area, whose),
                  {static_cast<int>(t)}, {}, {x[0], x[1], x[2]}, {}, -1};
      v.region = r;
      add(std::move(v));
    }
  }

  double average_lepp_size() const {
    std::size_t total = 0, count = 0;
    for (std::size_t t = 0; t < mesh_.triangles.size(); ++t) {
      if (!tri_ok_[t]) continue;
      ++count;
      std::size_t cur = t, size = 1;
      while (size <= mesh_.triangles.size()) {
        const int h = longest_half(cur), g = twin_[static_cast<std::size_t>(h)];
        if (g < 0 || constrained_half_[static_cast<std::size_t>(h)]) break;  // constrained or boundary terminal edge
        const std::size_t next = static_cast<std::size_t>(g / 3);
        ++size;
        if (longest_half(next) == g) break;  // terminal pair: t2 counted
        cur = next;
      }
      total += size;
    }
    return count ? static_cast<double>(total) / static_cast<double>(count) : 0;
  }

  void compute_statistics() {
    Statistics& s = report_.stats;
    Mesh valid;
    valid.vertices = mesh_.vertices;
    for (std::size_t t = 0; t < mesh_.triangles.size(); ++t)
      if (tri_ok_[t]) valid.triangles.push_back(T(t));
    const MeshStats m = mesh_stats(valid, pslg_);
    s.vertices = mesh_.vertices.size();
    s.triangles = mesh_.triangles.size();
    s.edges = edges_.size();
    s.min_angle_deg = m.min_angle_deg;
    s.avg_min_angle_deg = m.avg_min_angle_deg;
    s.min_area_quality = m.min_area_quality;
    s.shortest_edge = m.shortest_edge;
    s.shortest_edge_ratio = m.shortest_edge_ratio;
    s.avg_lepp_size = average_lepp_size();
  }
};

}  // namespace

double segment_tolerance(const Point& a, const Point& b, std::size_t interior_vertices) {
  const double m = std::max({std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y)});
  if (m == 0) return 0;
  int exponent = 0;
  std::frexp(m, &exponent);  // m = f * 2^exponent, f in [0.5, 1): ulp(m) = 2^(exponent - 53)
  const double ulp = std::ldexp(1.0, std::max(exponent - 53, -1074));
  return static_cast<double>(interior_vertices + 1) * ulp;
}

Report certify(const Pslg& pslg, const Mesh& mesh, const Options& options) {
  Report report;
  Certifier(pslg, mesh, options, report).run();
  return report;
}

}  // namespace lepp::certify
