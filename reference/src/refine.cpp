// SPDX-License-Identifier: GPL-3.0-or-later
// The refinement loop (ALGORITHM.md Sections 7 to 9): queue of bad triangles
// (bad_queue.h: the order), "while t remains", guards, trace, result.
#include <algorithm>
#include <chrono>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "lepp/angle.h"
#include "lepp/reference.h"
#include "bad_queue.h"
#include "triangulation.h"

namespace lepp::reference {

namespace {

using namespace detail;

std::string tri_string(const Tri& t) { return fmt::format("({},{},{})", t[0], t[1], t[2]); }

// For a guard outcome: the triangle being processed and its Lepp.
std::string describe(const Tri& bad, const Lepp& lepp) {
  std::string s = "triangle " + tri_string(bad) + ", Lepp";
  for (FH f : lepp.path) s += " " + tri_string(ccw_ids(f));
  int l = lepp.edge;
  s += fmt::format(", terminal edge ({},{})", id(lepp.t1->vertex(Cdt::ccw(l))), id(lepp.t1->vertex(Cdt::cw(l))));
  return s;
}

class Refiner {
 public:
  Refiner(const Pslg& pslg, const RefineOptions& options)
      : options_(options),
        sin2_(engine_sin2_threshold(options.min_angle_deg)),
        twice_max_area_(FT(options.max_area) * 2),
        budget_(options.max_steiner >= 0 ? options.max_steiner : default_steiner_budget(pslg, options)) {
    double floor = options.edge_floor >= 0 ? options.edge_floor : default_edge_floor(pslg);
    floor2_ = FT(floor) * FT(floor);
    build_triangulation(pslg, tr_);
    // Twice the size bound of each region (index 0: no region), the smaller of
    // the region's and max_area where both are set; none where neither is.
    bounds_.push_back(options.max_area > 0 ? std::optional<FT>(twice_max_area_) : std::nullopt);
    if (options.region_area_bounds) {
      assign_regions(tr_);
      for (const Region& r : pslg.regions) {
        std::optional<FT> b = bounds_[0];
        if (r.max_area > 0 && (!b || FT(r.max_area) * 2 < *b)) b = FT(r.max_area) * 2;
        bounds_.push_back(b);
      }
    }
  }

  RefineResult run() {
    auto start = std::chrono::steady_clock::now();
    tr_.cocircular_ties = count_cocircular_edges(tr_);
    std::vector<Queued> initial;
    for (FH f : tr_.cdt.finite_face_handles())
      if (f->info().in_domain && processed_bad(f)) initial.push_back(queued(f));
    queue_.push(initial, true);

    Outcome outcome = Outcome::Converged;
    std::string stuck;
    while ((!queue_.empty() || requeue_stopped()) && outcome == Outcome::Converged) {
      Tri t = queue_.pop();
      FH f;
      bool first = true;
      // "while t remains in tau": the triangle with t's three vertices.
      while (outcome == Outcome::Converged && exists(t, f)) {
        Lepp lepp = find_lepp(f, &longest_memo_);
        double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (options_.time_limit_seconds > 0 && elapsed > options_.time_limit_seconds) {
          outcome = Outcome::TimeLimit, stuck = describe(t, lepp);
          break;
        }
        if (steiner_ >= budget_) {
          outcome = Outcome::SteinerBudget, stuck = describe(t, lepp);
          break;
        }
        Selection s = select_point(lepp, options_.method);
        if (!settle_selection(tr_, lepp, options_.method, s)) {  // at the limit (section 8b)
          if (!other_tie_resolution(tr_, f, options_.method, lepp, s)) {  // the precision stop
            ++result_.precision_stops;
            stopped_.push_back({t, s.rule, s.point});
            break;
          }
          ++result_.tie_resolutions;
        }
        if (first && too_big(f)) ++result_.area_refined;
        first = false;
        ++result_.lepp_searches;
        result_.lepp_triangles += static_cast<std::int64_t>(lepp.path.size());
        std::string where = describe(t, lepp);  // before the insertion invalidates the faces
        if (options_.trace) result_.trace.push_back(trace_step(t, lepp, s));

        FH kept;
        VH v = insert_point(tr_, s, lepp.t1, options_.order == QueueOrder::Flip ? &created_ : nullptr, &kept);
        ++steiner_;
        enqueue_new_bad(v, kept);
        if (options_.on_insertion) options_.on_insertion(extract_mesh(tr_));
        if (options_.on_progress && steiner_ % 1000 == 0) options_.on_progress(steiner_);
        if (below_edge_floor(v)) outcome = Outcome::EdgeFloor, stuck = where;
      }
    }

    if (outcome == Outcome::Converged) check_nothing_left();
    for (FH f : tr_.cdt.finite_face_handles()) {
      if (!f->info().in_domain || !is_skinny(f, sin2_)) continue;
      if (auto u = unimprovable(tr_, f, sin2_)) result_.unimprovable.push_back(*u);
    }
    // The precision-stopped triangles still there (section 8b), once each, unless
    // section 8 lists them.
    std::map<Tri, const Stopped*> stopped_left;
    for (const Stopped& st : stopped_) {
      FH f;
      if (exists(st.t, f) && !(is_skinny(f, sin2_) && unimprovable(tr_, f, sin2_))) stopped_left[sorted(st.t)] = &st;
    }
    for (const auto& [k, st] : stopped_left) {
      FH f;
      exists(st->t, f);
      UnimprovableTriangle u;
      u.triangle = ccw_ids(f);
      u.reason = LeftReason::DoublePrecision;
      u.rule = st->rule;
      u.point = st->point;
      result_.unimprovable.push_back(u);
    }
    std::sort(result_.unimprovable.begin(), result_.unimprovable.end(),
              [](const UnimprovableTriangle& a, const UnimprovableTriangle& b) { return sorted(a.triangle) < sorted(b.triangle); });
    if (outcome == Outcome::Converged && !result_.unimprovable.empty()) outcome = Outcome::Unimprovable;

    result_.mesh = extract_mesh(tr_);
    result_.outcome = outcome;
    result_.stuck = stuck;
    result_.steiner_points = steiner_;
    result_.cocircular_ties = tr_.cocircular_ties;
    result_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return std::move(result_);
  }

 private:
  // A bad triangle the precision stop left: retried when the queue runs dry if
  // points were inserted since (its Lepp may have changed), listed otherwise.
  struct Stopped {
    Tri t;
    Rule rule;
    Point point;
  };
  bool requeue_stopped() {
    if (steiner_ == refill_mark_ || stopped_.empty()) return false;
    refill_mark_ = steiner_;
    std::vector<Queued> again;
    std::vector<Tri> seen;
    FH f;
    for (const Stopped& st : stopped_)
      if (exists(st.t, f) && std::find(seen.begin(), seen.end(), sorted(st.t)) == seen.end()) {
        seen.push_back(sorted(st.t));
        again.push_back(queued(f));
      }
    stopped_.clear();
    queue_.push(again, true);  // as the initial queue (section 7's order)
    return !queue_.empty();
  }
  bool is_stopped(FH f) const {
    const Tri k = key(f);
    for (const Stopped& st : stopped_)
      if (sorted(st.t) == k) return true;
    return false;
  }

  static Tri sorted(Tri t) {
    std::sort(t.begin(), t.end());
    return t;
  }

  bool exists(const Tri& t, FH& f) const {
    auto v = [&](int i) { return tr_.vertex[static_cast<std::size_t>(t[static_cast<std::size_t>(i)])]; };
    return tr_.cdt.is_face(v(0), v(1), v(2), f) && f->info().in_domain;
  }

  // ALGORITHM.md Section 4: bad = skinny or too big; processed unless skinny,
  // not too big and unimprovable.
  bool too_big(FH f) const {
    const std::optional<FT>& bound = bounds_[static_cast<std::size_t>(f->info().region)];
    return bound && is_too_big(f, *bound);
  }

  bool processed_bad(FH f) const {
    bool skinny = is_skinny(f, sin2_);
    bool big = too_big(f);
    if (!skinny && !big) return false;
    if (big) return true;
    return !unimprovable(tr_, f, sin2_);
  }

  Queued queued(FH f) const {
    return Queued{key(f), options_.order == QueueOrder::SmallestAngle ? smallest_angle_sin2(f) : FT(0)};
  }

  // The insertion's batch: the processed-bad triangles around v, for the flip
  // order in the order the insertion created them (the created ones that still exist).
  void enqueue_new_bad(VH v, FH kept) {
    std::vector<Queued> fresh;
    if (options_.order == QueueOrder::Flip) {
      FH f;
      for (const Tri& t : created_)
        if (exists(t, f) && processed_bad(f)) fresh.push_back(queued(f));
    } else {
      Cdt::Face_circulator fc = tr_.cdt.incident_faces(v), done = fc;
      do {
        if (!tr_.cdt.is_infinite(fc) && fc->info().in_domain && processed_bad(fc)) fresh.push_back(queued(fc));
      } while (++fc != done);
    }
    // A split off its line may keep a triangle beside its sliver (section 6): its
    // edge ab is no longer constrained, so it is judged again, last in creation order.
    if (kept != FH() && processed_bad(kept)) fresh.push_back(queued(kept));
    queue_.push(fresh, false);
  }

  bool below_edge_floor(VH v) const {
    Cdt::Vertex_circulator vc = tr_.cdt.incident_vertices(v), done = vc;
    do {
      if (!tr_.cdt.is_infinite(vc) && CGAL::squared_distance(v->point(), vc->point()) < floor2_) return true;
    } while (++vc != done);
    return false;
  }

  TraceStep trace_step(const Tri& bad, const Lepp& lepp, const Selection& s) const {
    TraceStep step;
    FH f;
    exists(bad, f);
    step.bad = ccw_ids(f);
    for (FH g : lepp.path) step.lepp.push_back(ccw_ids(g));
    int l = lepp.edge;
    step.terminal_edge = {id(lepp.t1->vertex(Cdt::ccw(l))), id(lepp.t1->vertex(Cdt::cw(l)))};
    step.t1 = ccw_ids(lepp.t1);
    if (lepp.t2 != FH()) step.t2 = ccw_ids(lepp.t2);
    step.rule = s.rule;
    step.point = s.point;
    if (s.split_face != FH()) {
      int i = s.split_index;
      step.split_segment = tr_.segment_of_edge.at(
          edge_key(id(s.split_face->vertex(Cdt::ccw(i))), id(s.split_face->vertex(Cdt::cw(i)))));
    }
    return step;
  }

  // Every triangle an insertion makes is incident to the new point and was
  // examined there: a processed bad triangle left at the end is a bug.
  void check_nothing_left() const {
    for (FH f : tr_.cdt.finite_face_handles())
      if (f->info().in_domain && processed_bad(f) && !is_stopped(f))
        throw std::logic_error("reference: bad triangle " + tri_string(ccw_ids(f)) + " left after the queue emptied");
  }

  const RefineOptions& options_;
  FT sin2_, twice_max_area_, floor2_;
  std::vector<std::optional<FT>> bounds_;  // by FaceInfo::region
  std::int64_t budget_;
  std::int64_t steiner_ = 0;
  std::vector<Stopped> stopped_;
  std::int64_t refill_mark_ = 0;
  Triangulation tr_;
  BadQueue queue_{options_.order, options_.order_seed};
  LongestEdgeMemo longest_memo_;
  std::vector<Tri> created_;  // the flip order: the last insertion's triangles, in creation order
  RefineResult result_;
};

}  // namespace

RefineResult refine(const Pslg& pslg, const RefineOptions& options) {
  auto start = std::chrono::steady_clock::now();
  Refiner refiner(pslg, options);
  RefineResult result = refiner.run();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace lepp::reference
