// SPDX-License-Identifier: GPL-3.0-or-later
// The replay's search for a choice (docs/AUDIT.md, "Conformance"): around the
// point, backwards along the Lepp tree to a bad triangle; then in the meshes
// that differ in cocircular cells (cocircular_search.cpp); then everywhere.
// And the insertion, as the reference engine inserts, and Theorem 2.
#include "replayer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <set>
#include <stdexcept>
#include <utility>

#include "distance_filter.h"
#include "insert_unflipped.h"
#include "lepp/angle.h"

namespace lepp::audit::replay_detail {
namespace {

// The input as a program that reads it as float holds it (MeshReading::FloatInput).
Pslg at_float_rounding(const Pslg& p) {
  Pslg rounded = p;
  std::map<std::pair<double, double>, std::size_t> seen;
  for (std::size_t i = 0; i < rounded.vertices.size(); ++i) {
    Point& v = rounded.vertices[i];
    v = {nearest_float(v.x), nearest_float(v.y)};
    if (const auto [at, fresh] = seen.emplace(std::make_pair(v.x, v.y), i); !fresh)
      throw std::invalid_argument("replay: rounded to float, input vertices " + std::to_string(at->second) + " and " +
                                  std::to_string(i) + " are one point");
  }
  return rounded;
}

}  // namespace

Replayer::Replayer(const Pslg& p, const ReplayRules& r)
    : pslg(r.mesh == MeshReading::FloatInput ? at_float_rounding(p) : p), rules(r) {
  // Every rule below becomes an exact number: a NaN or an infinity would be
  // GMP's invalid operation (SIGFPE), so they are refused here.
  if (!(r.min_angle_deg > 0 && r.min_angle_deg < 60))
    throw std::invalid_argument("replay: the angle must be between 0 and 60 degrees");
  if (!std::isfinite(r.angle_tolerance_deg) || !std::isfinite(r.point_tolerance_ulps))
    throw std::invalid_argument("replay: the angle and point tolerances must be finite");
  double theta = std::min(r.min_angle_deg + std::max(r.angle_tolerance_deg, 0.0), 60.0);
  sin2_ = FT(sin2_bracket(theta).hi);
  sin2_rounding_ = FT(sin2_bracket(r.min_angle_deg).hi) + FT(kThresholdRounding);
  build_triangulation(pslg, tr);
  bounds_.push_back(r.max_area > 0 ? std::optional<FT>(FT(r.max_area) * 2) : std::nullopt);
  if (r.region_area_bounds) {
    assign_regions(tr);
    for (const Region& region : pslg.regions) {
      std::optional<FT> b = bounds_[0];
      if (region.max_area > 0 && (!b || FT(region.max_area) * 2 < *b)) b = FT(region.max_area) * 2;
      bounds_.push_back(b);
    }
  }
  // The initial CDT's cocircular edges count as ties, as in the engines
  // (docs/ALGORITHM.md section 6): another implementation may have the other diagonal.
  tr.cocircular_ties = count_cocircular_edges(tr);
}

bool Replayer::judge_bad(FH f) const {
  if (is_skinny(f, sin2_) || (threshold_within_rounding_ && within_rounding_of_theta(f))) return true;
  const std::optional<FT>& b = bound(f->info().region);
  return b && is_too_big(f, *b);
}

bool Replayer::maybe_bad(FH f) const { return bad_of(facts_.of(f), f); }

bool Replayer::longest(FH f, int i) const { return longest_of(facts_.of(f), f, i); }

bool Replayer::bad_of(FaceFacts::Facts& e, FH f) const {
  if (!cache_face_facts) return judge_bad(f);
  std::int8_t& bad = e.bad[threshold_within_rounding_];
  if (bad == FaceFacts::kUnknown) bad = judge_bad(f);
  return bad;
}

bool Replayer::longest_of(FaceFacts::Facts& e, FH f, int i) const {
  if (!cache_face_facts) return is_longest(f, i);
  std::int8_t& mask = e.longest[length_ties_within_rounding];
  if (mask == FaceFacts::kUnknown) {
    mask = 0;
    for (int k = 0; k < 3; ++k) mask = static_cast<std::int8_t>(mask | is_longest(f, k) << k);
  }
  return mask >> i & 1;
}

bool Replayer::allows(Deviation d) const {
  return d == rules.variant || std::find(allowed_.begin(), allowed_.end(), d) != allowed_.end();
}

// Some allowed variant has points of its own (InexactLength has none: it changes
// the length comparisons), so the catalogue's points are worth computing.
bool Replayer::allows_points() const {
  auto points = [](Deviation d) {
    return d != Deviation::Unknown && d != Deviation::InexactLength && d != Deviation::InexactThreshold;
  };
  return points(rules.variant) || std::any_of(allowed_.begin(), allowed_.end(), points);
}

std::pair<double, double> Replayer::differences(const Point& p, const Candidate& c) {
  return {difference_to_double(p.x, c.point.x(), c.mean.x.data(), c.mean.n),
          difference_to_double(p.y, c.point.y(), c.mean.y.data(), c.mean.n)};
}

double Replayer::distance(const Point& p, const Candidate& c) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return std::numeric_limits<double>::infinity();
  const auto [dx, dy] = differences(p, c);
  return std::max(std::abs(dx), std::abs(dy));
}

void Replayer::set_distances(const Point& p, const Candidate& c, ReplayChoice& r) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
    r.distance = r.euclidean = std::numeric_limits<double>::infinity();
    return;
  }
  const auto [dx, dy] = differences(p, c);  // once for both
  r.distance = std::max(std::abs(dx), std::abs(dy));
  r.euclidean = std::hypot(dx, dy);
}

// The domain triangles around p: those incident to a vertex of the
// triangle(s) containing it (a point within tolerance of a choice lies in
// or next to the choice's terminal triangles). wide: one ring more, for a
// midpoint rounded half an ulp beyond its constrained edge, past a sliver
// there into a triangle that shares no vertex with the terminal pair.
std::vector<FH> Replayer::faces_near(const Point& p, bool& at_vertex, bool wide) {
  Cdt::Locate_type lt;
  int li;
  FH f = tr.cdt.locate(CPoint(p.x, p.y), lt, li, hint());
  at_vertex = lt == Cdt::VERTEX;
  std::vector<FH> out;
  std::set<FH> seen;
  if (f == FH()) return out;
  std::vector<VH> around;
  for (int i = 0; i < 3; ++i) around.push_back(f->vertex(i));
  if (lt == Cdt::EDGE) around.push_back(f->neighbor(li)->vertex(f->neighbor(li)->index(f)));
  for (VH v : around)
    if (!tr.cdt.is_infinite(v)) domain_faces_around(v, out, seen);
  if (!wide) return out;
  std::set<VH> ring(around.begin(), around.end());
  const std::size_t inner = out.size();
  for (std::size_t k = 0; k < inner; ++k)
    for (int i = 0; i < 3; ++i) {
      VH v = out[k]->vertex(i);
      if (ring.insert(v).second) domain_faces_around(v, out, seen);
    }
  return out;
}

// Every domain face around v, in the order of CGAL's circulator, each not yet
// seen added to out. None around a corner of the far bounding box
// (cdt_build.cpp): its faces are flooded out of the domain when it is built,
// and a later face takes its flags from the faces it is made of (a split, a flip). A corner's degree
// grows with the boundary's Steiner points (each outside triangle between a
// side of the domain and the box fans from a corner), and a point located in
// one of those triangles (on a boundary edge, or rounded just past it) had
// the search turn the whole fan at every step.
void Replayer::domain_faces_around(VH v, std::vector<FH>& out, std::set<FH>& seen) {
  if (skip_box_corners && id(v) < 0) return;
  Cdt::Face_circulator fc = tr.cdt.incident_faces(v), done = fc;
  do {
    ++star_faces_walked_;
    if (in_domain(fc) && seen.insert(fc).second) out.push_back(fc);
  } while (++fc != done);
}

// Terminal configurations with a terminal triangle in faces, each once.
std::vector<Terminal> Replayer::terminals(const std::vector<FH>& faces) const {
  std::vector<Terminal> out;
  std::set<std::pair<int, int>> seen;  // terminal edge by vertex ids
  for (FH f : faces) {
    for (int l = 0; l < 3; ++l) {
      if (!longest(f, l)) continue;
      auto e = edge_key(id(f->vertex(Cdt::ccw(l))), id(f->vertex(Cdt::cw(l))));
      if (f->is_constrained(l)) {
        // A constrained edge is terminal on each domain side separately.
        out.push_back({f, FH(), l});
        continue;
      }
      FH n = f->neighbor(l);
      if (!in_domain(n) || !longest(n, n->index(f))) continue;
      if (!seen.insert(e).second) continue;
      out.push_back({f, n, l});
    }
  }
  return out;
}

// Backwards from terminal triangle t (arrived at, terminal edge l; other
// the triangle across l or null) along the Lepp tree to a bad triangle,
// breadth first. Returns the Lepp from the bad triangle to t, empty if none.
std::vector<FH> Replayer::bad_reaching(FH t, int l, FH other) const {
  struct Node {
    FH f;
    int exit;  // the edge towards t
    int next;  // the node of the next face on its Lepp, -1 at t
    FaceFacts::Facts* facts;
  };
  // Reached faces carry this walk's mark in their entries (face_facts.h, kept
  // with or without cache_face_facts). One look-up a face: an entry stays where
  // it is while the walk adds others.
  const std::uint64_t walk = facts_.new_walk();
  std::vector<Node> nodes{{t, l, -1, &facts_.of(t)}};
  nodes[0].facts->walk = walk;
  if (other != FH()) facts_.of(other).walk = walk;
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const Node n = nodes[k];
    if (bad_of(*n.facts, n.f)) {
      std::vector<FH> path;
      for (int i = static_cast<int>(k); i >= 0; i = nodes[static_cast<std::size_t>(i)].next)
        path.push_back(nodes[static_cast<std::size_t>(i)].f);
      return path;
    }
    for (int i = 0; i < 3; ++i) {
      if (i == n.exit || n.f->is_constrained(i)) continue;
      FH g = n.f->neighbor(i);
      if (!in_domain(g)) continue;
      FaceFacts::Facts& e = facts_.of(g);
      if (e.walk == walk) continue;
      int gi = g->index(n.f);
      // g's Lepp (under some tie resolution) crosses into f: the shared
      // edge is a longest edge of g (and no longer than f's exit, always).
      if (!longest_of(e, g, gi)) continue;
      e.walk = walk;
      nodes.push_back({g, gi, static_cast<int>(k), &e});
    }
  }
  return {};
}

ReplayChoice Replayer::describe(const Terminal& t, const Candidate& c, const Point& p, const std::vector<FH>& path) const {
  ReplayChoice r;
  if (!path.empty()) {
    r.bad = ccw_ids(path.front());
    for (FH f : path) r.lepp.push_back(ccw_ids(f));
  }
  r.terminal_edge = {id(t.t1->vertex(Cdt::ccw(t.l))), id(t.t1->vertex(Cdt::cw(t.l)))};
  r.t1 = ccw_ids(t.t1);
  if (t.t2 != FH()) r.t2 = ccw_ids(t.t2);
  r.rule = c.rule;
  r.point = rounded_point(c);
  set_distances(p, c, r);
  r.tolerance = tolerance(c.scale);
  if (c.split_a != VH()) r.split_edge = {id(c.split_a), id(c.split_b)};
  r.deviation = c.deviation;
  return r;
}

// p inserted as candidate c of terminal t passes the precision stop's test
// (ALGORITHM.md section 8b): the split of c's edge at p makes counter-clockwise
// triangles, or p lies in the closed pair, beyond the precision floor.
bool Replayer::insertable_as(const Point& p, const Terminal& t, const Candidate& c) const {
  Selection s;
  s.point = p;
  if (c.split_a != VH()) {
    FH f;
    int i;
    if (!tr.cdt.is_edge(c.split_a, c.split_b, f, i)) return false;
    if (!in_domain(f)) {
      FH n = f->neighbor(i);
      i = n->index(f), f = n;
    }
    s.split_face = f, s.split_index = i;
  }
  Lepp lepp;
  lepp.t1 = t.t1, lepp.t2 = t.t2, lepp.edge = t.l;
  return insertable(tr, s, lepp);
}

// At the precision limit several choices lie within the tolerance of p (a
// midpoint a few ulps off its edge is also near the midpoint of the next
// one; at subnormal coordinates the tolerance spans several choices): the
// nearest that can be inserted at p is taken (the first of equally near
// ones), else the first. Not the first insertable: a centroid 8 ulps away,
// inserted into a face, keeps the constraint that the program's midpoint 0
// ulps away split, and the replay's mesh leaves the program's.
bool Replayer::match_here(const Point& p, ReplayChoice& out, bool wide) {
  bool at_vertex = false, found = false, insertable_found = false;
  double nearest = 0;
  std::vector<FH> faces = faces_near(p, at_vertex, wide);
  if (at_vertex) return false;
  for (const Terminal& t : terminals(faces)) {
    std::vector<Candidate> cands = candidates(t, &p);
    for (const Candidate& c : cands) {
      const double tol = tolerance(c.scale);
      if (surely_farther(p, c.point, tol)) continue;
      const double d = distance(p, c);
      if (d > tol || (insertable_found && d >= nearest)) continue;
      // The Lepp may arrive from either side of an unconstrained terminal edge.
      std::vector<FH> path = bad_reaching(t.t1, t.l, t.t2);
      Terminal used = t;
      if (path.empty() && t.t2 != FH()) {
        path = bad_reaching(t.t2, t.t2->index(t.t1), t.t1);
        if (!path.empty()) used = {t.t2, t.t1, t.t2->index(t.t1)};
      }
      if (path.empty()) continue;
      if (used.t2 != FH()) path.push_back(used.t2);
      if (insertable_as(p, used, c)) {
        out = describe(used, c, p, path);
        if (d == 0) return true;  // none nearer
        insertable_found = found = true;
        nearest = d;
        continue;
      }
      if (!found) out = describe(used, c, p, path), found = true;
    }
  }
  return found;
}

// p is a choice of the replay's mesh, or of another constrained Delaunay
// mesh of the same points: any triangulation of each cocircular cell (then
// the flips that make it are kept: the implementation evidently has that
// mesh). When that bounded search gives up: a mesh one or two cocircular
// flips away near p or where recent insertions met ties, or CGAL's
// perturbed constrained Delaunay mesh (then the replay follows CGAL's tie
// rule from here on). The search of the cells comes first because it is
// the cheapest: on a lattice box turned by -90 degrees (conformance_bench),
// 6 ms for the whole trace against 53 ms with the local flips tried first.
// That search is match_paper; where the lengths' near ties are allowed
// (InexactLength) and it fails, it runs again with them as ties, and a choice
// found so is tagged InexactLength.
// Likewise the threshold (InexactThreshold): triangles within double
// rounding above theta count as bad too, and with both allowed, both at once.
bool Replayer::match(const Point& p, ReplayChoice& out) {
  if (match_paper(p, out)) return true;
  const bool lengths = allows(Deviation::InexactLength), threshold = allows(Deviation::InexactThreshold);
  if (lengths) {
    LengthTiesWithinRounding relaxed(true);
    if (match_paper(p, out)) return out.deviation = Deviation::InexactLength, true;
  }
  if (!threshold) return false;
  threshold_within_rounding_ = true;
  struct Restore {
    bool& flag;
    ~Restore() { flag = false; }
  } restore{threshold_within_rounding_};
  if (match_paper(p, out)) return out.deviation = Deviation::InexactThreshold, true;
  if (!lengths) return false;
  LengthTiesWithinRounding relaxed(true);
  if (match_paper(p, out)) return out.deviation = Deviation::InexactThreshold, true;
  return false;
}

bool Replayer::match_paper(const Point& p, ReplayChoice& out) {
  search_exhausted_ = false;
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
  if (match_here(p, out) || match_here(p, out, true)) return true;
  if (rules.follow_cocircular_flips && match_cocircular(p, out)) return true;
  return match_everywhere(p, out);
}

// The last search, before a step is declared no choice: every bad triangle's
// Lepp, wherever its terminal pair lies, and the nearest choice within the
// tolerance that can be inserted (else the nearest). The searches around p
// miss a pair when p is located far from it: a boundary edge's midpoint
// rounded one ulp off its line to the outside of the domain lies in an
// outside triangle whose neighbours need not touch the pair (docs/CONFORMANCE.md,
// "A midpoint outside the domain"). Slow (the whole mesh), so only here.
bool Replayer::match_everywhere(const Point& p, ReplayChoice& out) {
  bool found = false, insertable_found = false;
  double nearest = 0;
  for_each_bad_lepp_end([&](const std::vector<FH>& lepp, const Terminal& t) {
    // The catalogue's points (both readings' centroids) only where a variant allows them.
    const bool area = rules.centroid == CentroidReading::Area || allows_points();
    if (far_from(p, terminal_bound(t), area, 1, -std::numeric_limits<double>::infinity())) return;
    for (const Candidate& c : candidates(t)) {
      const double tol = tolerance(c.scale);
      if (surely_farther(p, c.point, tol)) continue;
      const double d = distance(p, c);
      if (d > tol) continue;
      const bool ins = insertable_as(p, t, c);
      const bool better = !found || (ins && !insertable_found) || (ins == insertable_found && d < nearest);
      if (!better) continue;
      out = describe(t, c, p, lepp);
      found = true;
      insertable_found = ins;
      nearest = d;
    }
  });
  if (found) ++searched_everywhere_;
  return found;
}

void Replayer::insert(const Point& p, const ReplayChoice& choice) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) throw std::runtime_error("not a finite point");
  Selection s;
  // A float program's point stands for the choice it computed before rounding:
  // the replay keeps that one, the program's own mesh (MeshReading::FloatPoints).
  s.point = rules.mesh == MeshReading::FloatPoints && std::isfinite(choice.point.x) && std::isfinite(choice.point.y) &&
                    choice.terminal_edge[0] >= 0
                ? choice.point
                : p;
  FH f;
  int i = -1;
  if (choice.split_edge[0] >= 0) {
    VH a = tr.vertex.at(static_cast<std::size_t>(choice.split_edge[0]));
    VH b = tr.vertex.at(static_cast<std::size_t>(choice.split_edge[1]));
    if (!tr.cdt.is_edge(a, b, f, i)) throw std::runtime_error("the edge to split is not in the mesh");
    if (!in_domain(f)) {  // a boundary edge: split from its domain side, as the engines do (insertable_as)
      FH n = f->neighbor(i);
      i = n->index(f), f = n;
    }
    s.split_face = f, s.split_index = i;
  } else {
    Cdt::Locate_type lt;
    f = tr.cdt.locate(CPoint(s.point.x, s.point.y), lt, i, hint());
    if (lt == Cdt::VERTEX) throw std::runtime_error("the point is already a vertex");
    if (lt == Cdt::EDGE && f->is_constrained(i)) s.split_face = f, s.split_index = i;  // exactly on a constrained edge
  }
  VH v;
  try {
    // The program's mesh (MeshReading): no flips, or flips decided in double.
    const bool split = s.split_face != FH();
    const bool program_flips = rules.mesh == MeshReading::DoubleIncircle || rules.mesh == MeshReading::TiesKept;
    const bool own_flips = rules.mesh == MeshReading::NoFlips || program_flips ||
                           (rules.mesh == MeshReading::NoFlipsButSplits && !split);
    v = own_flips ? insert_point_unflipped(tr, s, f) : insert_point(tr, s, f);
    if (program_flips) program_lawson(v);
  } catch (const std::logic_error& e) {
    throw std::runtime_error(e.what());
  }
  last_ = v;
  if (perturbed_) {
    std::vector<std::pair<FH, int>> todo;
    Cdt::Face_circulator fc = tr.cdt.incident_faces(v), done = fc;
    do todo.push_back({fc, fc->index(v)}); while (++fc != done);
    cocircular_flips_ += perturbed_lawson(todo);
  }
  record_ties(v);
}

// Forward: every end of Lepp(t) under every tie resolution (capped).
void Replayer::lepp_ends(FH f, int entry, std::vector<FH>& path, std::vector<std::pair<std::vector<FH>, Terminal>>& out,
                         std::size_t cap) const {
  for (int l = 0; l < 3; ++l) {
    if (!longest(f, l)) continue;
    if (out.size() >= cap) return;
    if (l == entry) continue;
    if (f->is_constrained(l)) {
      out.push_back({path, {f, FH(), l}});
      continue;
    }
    FH n = f->neighbor(l);
    if (!in_domain(n) || std::find(path.begin(), path.end(), n) != path.end()) continue;
    int j = n->index(f);
    if (longest(n, j)) {
      std::vector<FH> full = path;
      full.push_back(n);
      out.push_back({full, {f, n, l}});
    }
    path.push_back(n);
    // Continue through n only across an edge at least as long (a tie
    // resolved the other way, or a strictly longer edge).
    lepp_ends(n, j, path, out, cap);
    path.pop_back();
  }
}

// Theorem 2 on a choice's terminal pair, exactly: the angle at apex c of
// terminal edge ab is over 120 degrees iff dot(ca, cb) < 0 and
// 4 dot^2 > |ca|^2 |cb|^2.
Theorem2Check Replayer::theorem2(const ReplayChoice& choice) const {
  Theorem2Check out;
  if (choice.t2[0] < 0 || choice.terminal_edge[0] < 0) return out;  // a constrained terminal edge: not the theorem's case
  auto V = [&](int i) { return tr.vertex.at(static_cast<std::size_t>(i))->point(); };
  const int ia = choice.terminal_edge[0], ib = choice.terminal_edge[1];
  for (const Tri& t : {choice.t1, choice.t2}) {
    int ic = -1;
    for (int v : t)
      if (v != ia && v != ib) ic = v;
    if (ic < 0) continue;
    const CPoint &A = V(ia), &B = V(ib), &C = V(ic);
    const K::Vector_2 u = A - C, v = B - C;
    const FT dot = u * v;
    if (!(dot < 0) || !(4 * dot * dot > u.squared_length() * v.squared_length())) continue;
    out.holds = false;
    out.apex = ic;
    const double cosv = CGAL::to_double(dot) / std::sqrt(CGAL::to_double(u.squared_length()) * CGAL::to_double(v.squared_length()));
    out.angle_deg = std::acos(std::max(-1.0, std::min(1.0, cosv))) * 180 / M_PI;
    return out;
  }
  return out;
}

std::vector<ReplayChoice> Replayer::all_choices(const Point& p, std::size_t limit, std::size_t& total) const {
  std::vector<ReplayChoice> all;
  for_each_bad_lepp_end([&](const std::vector<FH>& lepp, const Terminal& t) {
    for (const Candidate& c : candidates(t)) all.push_back(describe(t, c, p, lepp));
  });
  std::sort(all.begin(), all.end(), [](const ReplayChoice& a, const ReplayChoice& b) { return a.distance < b.distance; });
  total = all.size();
  if (all.size() > limit) all.resize(limit);
  return all;
}

}  // namespace lepp::audit::replay_detail
