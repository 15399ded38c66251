// SPDX-License-Identifier: GPL-3.0-or-later
// The replay's state and searches behind lepp::audit::Replay: the exact mesh
// (the reference engine's triangulation and insertion), the bad-triangle
// rules, the search for a choice around a point (replayer.cpp), over the
// cocircular cells' other triangulations (cocircular_search.cpp) and the
// catalogue's diagnosis (diagnose.cpp).
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "catalogue_points.h"
#include "face_facts.h"
#include "paper_points.h"

namespace lepp::audit::replay_detail {

// The inexact-threshold variant: a triangle whose smallest angle alpha has
// sin^2 alpha < sin2_bracket(theta).hi + 16 DBL_EPSILON (exactly) may count as
// bad. A double program's "alpha < theta" flips only where |cos alpha - cos
// theta| is within its rounding (about 8 DBL_EPSILON: cos from a dot product
// or the law of cosines, and cos theta), and |sin^2 alpha - sin^2 theta| =
// |cos alpha - cos theta| (cos alpha + cos theta) <= 16 DBL_EPSILON; an atan2
// angle errs by a few DBL_EPSILON radians, which moves sin^2 by no more.
constexpr double kThresholdRounding = 16 * DBL_EPSILON;

class Replayer {
 public:
  Replayer(const Pslg& p, const ReplayRules& r);

  // replayer.cpp: the searches and the insertion (Replay's API).
  bool match(const Point& p, ReplayChoice& out);
  void insert(const Point& p, const ReplayChoice& choice);
  std::vector<ReplayChoice> all_choices(const Point& p, std::size_t limit, std::size_t& total) const;
  Theorem2Check theorem2(const ReplayChoice& choice) const;
  // diagnose.cpp: which catalogue rule p is.
  DeviationMatch diagnose(const Point& p) const;
  // program_lawson.cpp: Lawson flips around v as a program makes them, each
  // decided by the in-circle determinant evaluated in double
  // (MeshReading::DoubleIncircle) or exactly but strictly (TiesKept).
  void program_lawson(VH v);

  // From now on the variant's points are choices too (Replay::allow).
  void allow(Deviation variant) {
    if (has_variant(variant) && !allows(variant)) allowed_.push_back(variant);
  }

  Pslg pslg;  // a copy: the Triangulation keeps a pointer to it
  ReplayRules rules;
  Triangulation tr;
  std::int64_t cocircular_flips_ = 0;
  // Steps whose choice only the last search, over the whole mesh (match_everywhere),
  // found: the searches around the point and of the cocircular cells missed it.
  // For tests (a choice the search one ring wider must find:
  // audit/tests/replay/wider_search_test.cpp), and it shows how often the slow
  // search runs.
  std::int64_t searched_everywhere_ = 0;
  bool search_exhausted_ = false;  // the last match's search of the cells ran out of its budget
  // For tests: false builds every configuration's candidates in the whole-mesh
  // searches (match_everywhere, diagnose), as before far_from, and every catalogue
  // point in the search around a point (area_centroid_beyond); the answers must be
  // the same (audit/tests/replay/far_terminals_test.cpp).
  static inline bool skip_far_terminals = true;
  mutable std::int64_t skipped_terminals_ = 0;  // configurations far_from skipped (tests)
  // For tests: false computes every face's facts afresh (face_facts.h), as
  // before the cache (the walks still mark the faces they reach there); the
  // answers must be the same (audit/tests/replay/face_facts_test.cpp).
  static inline bool cache_face_facts = true;
  // For tests: false turns the faces around the far bounding box's corners in
  // faces_near too, as before domain_faces_around left them out; the faces and
  // the answers must be the same (audit/tests/replay/box_corners_test.cpp).
  static inline bool skip_box_corners = true;
  std::int64_t star_faces_walked_ = 0;  // faces faces_near turned around its vertices (tests)

  // A face's facts under the reading of the moment, from the cache (face_facts.h);
  // public for the tests that hold them against their computation.
  bool maybe_bad(FH f) const;  // bad, or within the angle tolerance of bad
  bool longest(FH f, int i) const;  // edge i is a longest edge of f (ties included)
  bool judge_bad(FH f) const;  // maybe_bad, computed
  const FaceFacts& face_facts() const { return facts_; }
  // The search's domain faces around p (replayer.cpp); public for the tests that
  // hold them against the whole turns of every vertex (box_corners_test.cpp).
  std::vector<FH> faces_near(const Point& p, bool& at_vertex, bool wide = false);

 private:
  FT sin2_;
  // sin^2 theta's certified upper end + 16 DBL_EPSILON (kThresholdRounding).
  FT sin2_rounding_;
  // Set around the searches that take triangles within double rounding of
  // theta as bad too (InexactThreshold allowed).
  mutable bool threshold_within_rounding_ = false;
  // Twice the size bound of each region (index 0: no region), as the reference
  // engine computes them (refine.cpp): the smaller of the region's and max_area.
  std::vector<std::optional<FT>> bounds_;
  VH last_;  // the last vertex inserted: where to start locating the next point
  // The variants whose points are choices too (ReplayRules::variant, allow()).
  std::vector<Deviation> allowed_;
  std::vector<EdgeIds> recent_ties_;
  bool perturbed_ = false;  // following CGAL's perturbed tie rule

  FH hint() const { return last_ != VH() ? last_->face() : FH(); }
  bool in_domain(FH f) const { return replay_detail::in_domain(tr, f); }
  double tolerance(double scale) const { return point_tolerance(rules, scale); }
  // True when no candidate at the configuration can be within `factor` times its
  // tolerance of p, nor nearer than `ratio` such tolerances: the whole-mesh
  // searches skip it without building one (TerminalBound). `area`: some
  // candidate may be of the area reading.
  bool far_from(const Point& p, const TerminalBound& b, bool area, double factor, double ratio) const {
    if (!skip_far_terminals) return false;
    const double tol = factor * tolerance(area ? b.area_scale : b.scale), lb = b.box.lower_bound(p);
    const bool far = lb > tol && lb / tol > ratio;
    skipped_terminals_ += far;
    return far;
  }

  mutable FaceFacts facts_;
  // maybe_bad and longest on f's entry e (filled on first use).
  bool bad_of(FaceFacts::Facts& e, FH f) const;
  bool longest_of(FaceFacts::Facts& e, FH f, int i) const;

  // Bad, or within the angle tolerance of bad.
  const std::optional<FT>& bound(int region) const { return bounds_[static_cast<std::size_t>(region)]; }
  bool maybe_bad(const CellTri& t) const;  // cocircular_search.cpp
  bool within_rounding_of_theta(FH f) const { return is_skinny(f, sin2_rounding_); }

  bool allows(Deviation d) const;
  bool allows_points() const;
  // Every point the paper's rule allows for this terminal configuration (and,
  // under ReplayRules::variant and allow(), the variants' points there).
  // near: the point searched around (catalogue_points may leave out what is surely
  // too far from it; skip_far_terminals false leaves out nothing).
  template <class T>
  std::vector<Candidate> candidates(const T& t1, const T& t2, bool has_t2, int l, const Point* near = nullptr) const {
    std::vector<Candidate> out = paper_candidates(rules, t1, t2, has_t2, l);
    if (allows_points())
      for (Candidate& c : catalogue_points(rules, t1, t2, has_t2, l, skip_far_terminals ? near : nullptr))
        if (allows(c.deviation)) out.push_back(c);
    return out;
  }
  std::vector<Candidate> candidates(const Terminal& t, const Point* near = nullptr) const {
    return t.t2 == FH() ? candidates(t.t1, t.t1, false, t.l, near) : candidates(t.t1, t.t2, true, t.l, near);
  }

  // From p to a candidate's point: max(|dx|, |dy|) (distance), and for a report both
  // it and the Euclidean distance from the same two differences (set_distances); each
  // difference as CGAL's to_double rounds it, without GMP where the point is a mean of
  // doubles (mean_difference.h).
  static double distance(const Point& p, const Candidate& c);
  static std::pair<double, double> differences(const Point& p, const Candidate& c);  // dx, dy of a finite p
  static void set_distances(const Point& p, const Candidate& c, ReplayChoice& r);

  // replayer.cpp: the search around a point, and everywhere.
  void domain_faces_around(VH v, std::vector<FH>& out, std::set<FH>& seen);
  std::vector<Terminal> terminals(const std::vector<FH>& faces) const;
  std::vector<FH> bad_reaching(FH t, int l, FH other) const;
  ReplayChoice describe(const Terminal& t, const Candidate& c, const Point& p, const std::vector<FH>& path) const;
  bool insertable_as(const Point& p, const Terminal& t, const Candidate& c) const;
  bool match_here(const Point& p, ReplayChoice& out, bool wide = false);
  bool match_paper(const Point& p, ReplayChoice& out);
  bool match_everywhere(const Point& p, ReplayChoice& out);  // counts searched_everywhere_
  void lepp_ends(FH f, int entry, std::vector<FH>& path, std::vector<std::pair<std::vector<FH>, Terminal>>& out,
                 std::size_t cap) const;
  // Calls f(lepp, terminal) for every Lepp end (under every tie resolution, at
  // most 64 each) of every domain triangle that may be bad.
  template <class F>
  void for_each_bad_lepp_end(F&& f) const {
    for (FH face : tr.cdt.finite_face_handles()) {
      if (!in_domain(face) || !maybe_bad(face)) continue;
      std::vector<FH> path{face};
      std::vector<std::pair<std::vector<FH>, Terminal>> ends;
      lepp_ends(face, -1, path, ends, 64);
      for (const auto& [lepp, t] : ends) f(lepp, t);
    }
  }

  // cocircular_search.cpp: the meshes that differ from the replay's in cocircular cells.
  struct PathNode {
    CellTri t;
    int exit;  // the edge towards the terminal edge
    int next;  // index of the next node on the Lepp, -1 at the terminal triangle
  };
  bool match_cocircular(const Point& p, ReplayChoice& out);
  bool cocircular(FH f, int i) const { return cocircular_edge(tr, f, i); }
  bool find_edge(const EdgeIds& e, FH& f, int& i) const;
  EdgeIds flip(FH f, int i);
  std::vector<EdgeIds> flip_candidates(const Point& p);
  std::int64_t perturbed_lawson(std::vector<std::pair<FH, int>> todo);
  bool spend(std::size_t& used);
  std::vector<CellTri> cell_bad_reaching(CellMap& cells, const CellTri& t, int l, const CellTri* other, std::size_t& used);
  bool try_cell_terminal(CellMap& cells, const CellTri& t1, const CellTri* t2, int l, const Point& p, ReplayChoice& out,
                         std::size_t& used);
  bool match_any_triangulation(const Point& p, ReplayChoice& out);
  bool match_local_flips(const Point& p, ReplayChoice& out);
  void record_ties(VH v);
};

}  // namespace lepp::audit::replay_detail
