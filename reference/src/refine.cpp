// SPDX-License-Identifier: GPL-3.0-or-later
// The refinement loop (ALGORITHM.md Sections 7 to 9): queue of bad triangles
// (bad_queue.h: the order), "while t remains", guards, trace, result.
#include <algorithm>
#include <chrono>
#include <map>
#include <optional>
#include <set>
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

// For a guard outcome: the triangle being processed and its Lepp, by ids (they
// outlive the faces an insertion destroys), written out only when a guard stops.
struct LeppIds {
  Tri bad{};
  std::vector<Tri> path;
  int a = -1, b = -1;  // the terminal edge
  void take(const Tri& t, const Lepp& lepp) {
    bad = t;
    path.clear();
    for (FH f : lepp.path) path.push_back(ccw_ids(f));
    a = id(lepp.t1->vertex(Cdt::ccw(lepp.edge)));
    b = id(lepp.t1->vertex(Cdt::cw(lepp.edge)));
  }
  std::string text() const {
    std::string s = "triangle " + tri_string(bad) + ", Lepp";
    for (const Tri& t : path) s += " " + tri_string(t);
    return s + fmt::format(", terminal edge ({},{})", a, b);
  }
};

std::string describe(const Tri& bad, const Lepp& lepp) {
  LeppIds ids;
  ids.take(bad, lepp);
  return ids.text();
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
    start_ = std::chrono::steady_clock::now();
    tr_.cocircular_ties = count_cocircular_edges(tr_);
    std::vector<Queued> initial;
    for (FH f : tr_.cdt.finite_face_handles())
      if (f->info().in_domain && processed_bad(f)) initial.push_back(queued(f));

    if (options_.order == QueueOrder::Batch)
      run_rounds(initial);
    else
      run_queue(initial);
    Outcome outcome = outcome_;
    const std::string stuck = stuck_;

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
      u.search_cut = st->cut;
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
    result_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    return std::move(result_);
  }

 private:
  // Every order but batch: one queue, each triangle refined while it remains (section 7).
  void run_queue(std::vector<Queued>& initial) {
    queue_.push(initial, true);
    while (outcome_ == Outcome::Converged && (!queue_.empty() || requeue_stopped())) {
      Tri t = queue_.pop();
      FH f;
      bool first = true;
      // "while t remains in tau": the triangle with t's three vertices.
      while (outcome_ == Outcome::Converged && exists(t, f)) {
        Lepp lepp = find_lepp(f, &longest_memo_);
        if (!guards_pass(t, lepp)) break;
        Selection s = select_point(lepp, options_.method);
        if (!settle(t, f, lepp, s)) break;
        std::vector<Queued> fresh = insert_selection(t, f, lepp, s, first);
        first = false;
        queue_.push(fresh, false);
      }
    }
  }

  // The batch order (section 7): rounds of triangles whose regions (Lepp, terminal
  // pair, the insertion's cavity and its ring) are apart, inserted in queue order.
  // Triangles are named by their keys: a key reserved or made in this round is touched.
  void run_rounds(std::vector<Queued>& initial) {
    std::sort(initial.begin(), initial.end(), [](const Queued& x, const Queued& y) { return x.key < y.key; });
    std::vector<Tri> round, next;
    for (const Queued& q : initial) round.push_back(q.key);
    while (outcome_ == Outcome::Converged) {
      if (round.empty()) {
        if (!requeue_stopped()) break;
        while (!queue_.empty()) round.push_back(queue_.pop());
      }
      std::set<Tri> touched;
      std::vector<Tri> tails;
      next.clear();
      bool closed = false;
      int members = 0;
      std::size_t looks = 0, rest = round.size();  // round[rest, ...) waits unlooked
      bool counted = false;
      for (std::size_t i = 0; i < round.size(); ++i) {
        const Tri& t = round[i];
        FH f;
        if (outcome_ != Outcome::Converged) break;
        // A closed round, or one past its looks (kBatchLooksPerMember per member and
        // kBatchFreeLooks more), leaves the rest of its queue as it is.
        if (closed || looks >= batch_looks_allowed(members)) {
          rest = i;
          break;
        }
        if (!exists(t, f)) continue;
        if (!counted) counted = true, ++result_.rounds;  // counted from its first triangle in the mesh
        if (touched.count(key(f))) {
          next.push_back(t);
          continue;
        }
        ++looks, ++result_.looks;
        Lepp lepp = find_lepp(f, &longest_memo_);
        bool apart = true;
        for (FH g : lepp.path) apart = apart && !touched.count(key(g));
        if (!apart) {
          next.push_back(t);
          continue;
        }
        Selection s = select_point(lepp, options_.method);
        if (plain(lepp, s)) {
          std::vector<Tri> region;
          for (FH g : lepp.path) region.push_back(key(g));
          if (!cavity_and_ring(s, lepp, touched, region)) {
            next.push_back(t);
            continue;
          }
          touched.insert(region.begin(), region.end());
          if (!guards_pass(t, lepp)) break;
        } else {
          // At the limit: only as the round's first member, on the round's mesh.
          if (members > 0) {
            next.push_back(t);
            continue;
          }
          if (!guards_pass(t, lepp)) break;
          if (!settle(t, f, lepp, s)) continue;  // left (the precision stop): nothing changed
          closed = true;  // its alternatives read beyond any region: the round ends with it
        }
        ++members;
        std::vector<Queued> fresh = insert_selection(t, f, lepp, s, true);
        for (const Tri& k : last_star_) touched.insert(k);
        std::sort(fresh.begin(), fresh.end(), [](const Queued& x, const Queued& y) { return x.key < y.key; });
        for (const Queued& q : fresh) tails.push_back(q.key);
        if (exists(t, f)) next.push_back(t);
      }
      // The next round: what waits, in this round's order, then each member's batch;
      // each triangle once, where it first comes.
      next.insert(next.end(), round.begin() + static_cast<std::ptrdiff_t>(rest), round.end());
      round.clear();
      std::set<Tri> queued;
      for (const std::vector<Tri>* list : {&next, &tails})
        for (const Tri& t : *list) {
          FH f;
          if (exists(t, f) && queued.insert(key(f)).second) round.push_back(t);
        }
    }
  }

  // A selection a round can take as it is: insertable as computed, and not a split
  // of a domain boundary edge rounded strictly outside the domain (section 7).
  bool plain(const Lepp& lepp, const Selection& s) const {
    if (s.split_face != FH()) {
      FH n = s.split_face->neighbor(s.split_index);
      const int i = s.split_index;
      if ((tr_.cdt.is_infinite(n) || !n->info().in_domain) &&
          CGAL::orientation(s.split_face->vertex(Cdt::ccw(i))->point(), s.split_face->vertex(Cdt::cw(i))->point(),
                            CPoint(s.point.x, s.point.y)) == CGAL::RIGHT_TURN)
        return false;
    }
    return insertable(tr_, s, lepp);
  }

  // The cavity of a plain selection (the domain faces holding its point, then
  // across unconstrained edges every domain face whose circumcircle holds it, on
  // the circle included) and its ring (the other domain faces sharing an edge with
  // it), appended to region by key; false as soon as one is touched.
  bool cavity_and_ring(const Selection& s, const Lepp& lepp, const std::set<Tri>& touched, std::vector<Tri>& region) const {
    const CPoint p(s.point.x, s.point.y);
    std::vector<FH> cavity;
    std::set<FH> in_cavity;  // a fan's cavity can hold thousands of faces: no scan per neighbour
    auto domain = [&](FH g) { return !tr_.cdt.is_infinite(g) && g->info().in_domain; };
    auto add = [&](FH g) {
      if (in_cavity.insert(g).second) cavity.push_back(g);
    };
    if (s.split_face != FH()) {
      add(s.split_face);
      if (FH n = s.split_face->neighbor(s.split_index); domain(n)) add(n);
    } else {
      for (FH g : {lepp.t1, lepp.t2}) {
        if (g == FH()) continue;
        CGAL::Orientation o[3];
        for (int i = 0; i < 3; ++i) o[i] = CGAL::orientation(g->vertex(Cdt::ccw(i))->point(), g->vertex(Cdt::cw(i))->point(), p);
        if (o[0] == CGAL::RIGHT_TURN || o[1] == CGAL::RIGHT_TURN || o[2] == CGAL::RIGHT_TURN) continue;
        add(g);
        for (int i = 0; i < 3; ++i)
          if (o[i] == CGAL::COLLINEAR && domain(g->neighbor(i))) add(g->neighbor(i));
        break;
      }
    }
    for (std::size_t k = 0; k < cavity.size(); ++k) {
      FH g = cavity[k];
      if (touched.count(key(g))) return false;
      for (int i = 0; i < 3; ++i) {
        FH n = g->neighbor(i);
        if (!domain(n) || in_cavity.count(n)) continue;
        const bool inside = !g->is_constrained(i) &&
                            CGAL::side_of_oriented_circle(n->vertex(0)->point(), n->vertex(1)->point(),
                                                          n->vertex(2)->point(), p) != CGAL::ON_NEGATIVE_SIDE;
        if (inside) {
          add(n);
        } else {
          if (touched.count(key(n))) return false;
          region.push_back(key(n));
        }
      }
    }
    for (FH g : cavity) region.push_back(key(g));
    return true;
  }

  // The guards before an insertion (section 9): false when one ends the run.
  bool guards_pass(const Tri& t, const Lepp& lepp) {
    double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (options_.time_limit_seconds > 0 && elapsed > options_.time_limit_seconds)
      outcome_ = Outcome::TimeLimit;
    else if (steiner_ >= budget_)
      outcome_ = Outcome::SteinerBudget;
    if (outcome_ == Outcome::Converged) return true;
    stuck_ = describe(t, lepp);
    return false;
  }

  // The selection as inserted (section 8b): false when no resolution of it can be
  // inserted (the precision stop leaves the triangle).
  bool settle(const Tri& t, FH f, Lepp& lepp, Selection& s) {
    if (settle_selection(tr_, lepp, options_.method, s)) return true;
    bool cut = false;
    if (!other_tie_resolution(tr_, f, options_.method, options_.tie_search_states, lepp, s, &cut)) {
      ++result_.precision_stops;
      stopped_.push_back({t, s.rule, s.point, cut});
      return false;
    }
    ++result_.tie_resolutions;
    return true;
  }

  // Inserts the settled selection for t, as every order does; returns the new
  // point's batch of processed bad triangles (last_star_: every domain face around it).
  std::vector<Queued> insert_selection(const Tri& t, FH f, const Lepp& lepp, const Selection& s, bool first) {
    if (first && too_big(f)) ++result_.area_refined;
    ++result_.lepp_searches;
    result_.lepp_triangles += static_cast<std::int64_t>(lepp.path.size());
    where_.take(t, lepp);  // before the insertion invalidates the faces; text only if the floor stops the run
    if (options_.trace) {
      result_.trace.push_back(trace_step(t, lepp, s));
      result_.trace.back().round = result_.rounds;
    }

    FH kept;
    VH v = insert_point(tr_, s, lepp.t1, options_.order == QueueOrder::Flip ? &created_ : nullptr, &kept);
    ++steiner_;
    last_star_.clear();
    Cdt::Face_circulator fc = tr_.cdt.incident_faces(v), done = fc;
    do {
      if (!tr_.cdt.is_infinite(fc) && fc->info().in_domain) last_star_.push_back(key(fc));
    } while (++fc != done);
    if (kept != FH()) last_star_.push_back(key(kept));
    std::vector<Queued> fresh = new_bad(v, kept);
    if (options_.on_insertion) options_.on_insertion(extract_mesh(tr_));
    if (options_.on_progress && steiner_ % 1000 == 0) options_.on_progress(steiner_);
    if (below_edge_floor(v)) outcome_ = Outcome::EdgeFloor, stuck_ = where_.text();
    return fresh;
  }

  // A bad triangle the precision stop left: retried when the queue runs dry if
  // points were inserted since (its Lepp may have changed), listed otherwise.
  struct Stopped {
    Tri t;
    Rule rule;
    Point point;
    bool cut;  // the tie search stopped at its bound
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
  std::vector<Queued> new_bad(VH v, FH kept) {
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
    return fresh;
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
  Outcome outcome_ = Outcome::Converged;
  std::string stuck_;
  LeppIds where_;  // the last insertion's triangle and Lepp, for an edge-floor stop
  std::chrono::steady_clock::time_point start_;
  std::vector<Tri> last_star_;  // the last insertion's domain faces around its point (and a kept one)
  std::vector<Tri> created_;  // the flip order: the last insertion's triangles, in creation order
  RefineResult result_;
};

}  // namespace

RefineResult refine(const Pslg& pslg, const RefineOptions& options) {
  auto start = std::chrono::steady_clock::now();
  Refiner refiner(pslg, options);  // builds the initial CDT
  const double cdt_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RefineResult result = refiner.run();
  result.cdt_seconds = cdt_seconds;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace lepp::reference
