// SPDX-License-Identifier: GPL-3.0-or-later
// The fast engine's refinement loop (ALGORITHM.md sections 7 to 9): the queue
// of bad triangles, guards, trace and statistics around Lepp search, point
// selection and insertion.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include <fmt/format.h>

#include "cdt_build.h"
#include "bad_queue.h"
#include "batch_rounds.h"
#include "capacity.h"
#include "insertion.h"
#include "lepp/angle.h"
#include "lepp/fast.h"
#include "lepp_search.h"
#include "point_selection.h"
#include "populate_ahead.h"
#include "precision_stop.h"
#include "quality.h"
#include "round_picks.h"
#include "tri_mesh.h"

namespace lepp::fast {
namespace {

using Clock = std::chrono::steady_clock;


// A triangle as the trace names it: counter-clockwise, smallest id first.
Tri canonical(const FTri& f) {
  Tri t{f.v(0), f.v(1), f.v(2)};
  while (t[0] > t[1] || t[0] > t[2]) t = {t[1], t[2], t[0]};
  return t;
}

std::string describe(const TriMesh& m, const Item& it, const Lepp& lepp) {
  Tri bad = canonical(m.t(it.tri));
  std::string s = fmt::format("triangle {} {} {}; Lepp", bad[0], bad[1], bad[2]);
  for (int ti : lepp.path) {
    Tri t = canonical(m.t(ti));
    s += fmt::format(" ({} {} {})", t[0], t[1], t[2]);
  }
  return s;
}

struct Bbox {
  double x0, y0, x1, y1;
};
Bbox bbox_of(const Pslg& pslg) {
  Bbox b{0, 0, 0, 0};
  if (pslg.vertices.empty()) return b;
  b = {pslg.vertices[0].x, pslg.vertices[0].y, pslg.vertices[0].x, pslg.vertices[0].y};
  for (const Point& p : pslg.vertices)
    b.x0 = std::min(b.x0, p.x), b.x1 = std::max(b.x1, p.x), b.y0 = std::min(b.y0, p.y), b.y1 = std::max(b.y1, p.y);
  return b;
}

class Refiner {
 public:
  Refiner(const Pslg& pslg, const RefineOptions& options)
      : pslg_(pslg),
        opt_(options),
        mem_(make_membership(pslg)),
        quality_(pslg, mem_, engine_sin2_threshold(options.min_angle_deg), options.max_area) {
    if (options.region_area_bounds) quality_.use_region_bounds(pslg.regions);
  }

  RefineResult run() {
    const auto start = Clock::now();
    const std::int64_t budget = opt_.max_steiner >= 0 ? opt_.max_steiner : default_steiner_budget(pslg_, opt_);
    const double floor = opt_.edge_floor >= 0 ? opt_.edge_floor : default_edge_floor(pslg_);
    const std::size_t n = pslg_.vertices.size();

    // Reserve from a size estimate: untouched capacity costs no resident memory.
    double expected = 4.0 * static_cast<double>(n) + 4096;
    if (opt_.max_area > 0) {
      Bbox b = bbox_of(pslg_);
      expected += 2.5 * (b.x1 - b.x0) * (b.y1 - b.y0) / opt_.max_area;
    }
    expected = std::min(expected, static_cast<double>(n) + static_cast<double>(budget) + 1);
    const auto vertices_guess = static_cast<std::size_t>(std::min(expected, 4e8));
    std::int64_t initial_ties = 0;
    // A triangulation of n vertices has fewer than 2 n triangles.
    check_capacity(static_cast<std::int64_t>(n), 2 * static_cast<std::int64_t>(n), kInputOnly);
    mesh_ = build_initial_cdt(pslg_, mem_, 2 * vertices_guess, vertices_guess, &initial_ties, opt_.region_area_bounds);
    if (opt_.region_area_bounds) {
      // Region bounds: the estimate from the initial triangles' areas over their bounds.
      double more = 0;
      for (int ti = 0; ti < mesh_.size(); ++ti) {
        const double bound = quality_.twice_bound(mesh_, ti);
        const FTri& f = mesh_.t(ti);
        const Point &a = mesh_.p(f.v(0)), &b = mesh_.p(f.v(1)), &c = mesh_.p(f.v(2));
        if (bound > 0) more += 2.5 * std::fabs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) / bound;
      }
      const double wanted = std::min(4.0 * static_cast<double>(n) + 4096 + more, static_cast<double>(n) + static_cast<double>(budget) + 1);
      if (wanted > expected) {
        const auto guess = static_cast<std::size_t>(std::min(wanted, 4e8));
        mesh_.reserve(guess, 2 * guess);
      }
      expected = std::max(expected, wanted);
    }
    const auto vertices_reserved = static_cast<std::size_t>(std::min(expected, 4e8));
    mem_.steiner_on.reserve(vertices_reserved / 64 + 1);
    const bool sized = quality_.sized();

    RefineResult result;
    result.cdt_seconds = std::chrono::duration<double>(Clock::now() - start).count();
    budget_ = budget;
    floor_ = floor;
    start_ = start;
    sized_ = sized;
    std::vector<Keyed> initial;
    for (int ti = 0; ti < mesh_.size(); ++ti)
      if (quality_.processed(mesh_, ti)) initial.push_back(keyed(mesh_, ti));
    if (opt_.order == QueueOrder::Batch)
      run_rounds(initial, result);
    else
      run_queue(initial, result);
    Outcome outcome = outcome_;
    const std::int64_t steiner = steiner_;

    // The unimprovable list, recomputed on the final mesh in key order (section 8),
    // then the precision-stopped triangles still there (section 8b: the last look
    // at each found no insertable point), once each, unless section 8 lists them.
    std::vector<Keyed> left;
    // By slot, the few stopped triangles still there: a map, not a pointer per
    // triangle (8 bytes each, alive when the output mesh is made: issue 31).
    std::unordered_map<int, const Stopped*> stopped_at;
    for (const Stopped& s : stopped_)
      if (still_there(mesh_, s.item)) stopped_at[s.item.tri] = &s;
    auto stopped_in = [&stopped_at](int ti) -> const Stopped* {
      if (stopped_at.empty()) return nullptr;
      const auto it = stopped_at.find(ti);
      return it == stopped_at.end() ? nullptr : it->second;
    };
    for (int ti = 0; ti < mesh_.size(); ++ti) {
      // The rule needs both ends of the shortest edge on segments: a triangle with
      // fewer than two such vertices (almost all) is not judged (issue 40).
      const FTri& f = mesh_.t(ti);
      const bool may_be_left = mem_.on_any(f.v(0)) + mem_.on_any(f.v(1)) + mem_.on_any(f.v(2)) >= 2;
      const bool angle_rule = may_be_left && quality_.judge(mesh_, ti).skinny &&
                              quality_.unimprovable(mesh_, ti, quality_.shortest_edge(mesh_, ti), nullptr);
      if (angle_rule) stopped_at.erase(ti);
      if (angle_rule || stopped_in(ti)) left.push_back(keyed(mesh_, ti));
    }
    std::sort(left.begin(), left.end(), KeyLess{});
    for (const Keyed& k : left) {
      UnimprovableTriangle u;
      if (const Stopped* s = stopped_in(k.item.tri)) {
        u.reason = LeftReason::DoublePrecision;
        u.rule = s->rule;
        u.point = s->point;
        u.search_cut = s->cut;
      } else {
        quality_.unimprovable(mesh_, k.item.tri, quality_.shortest_edge(mesh_, k.item.tri), &u);
      }
      u.triangle = canonical(mesh_.t(k.item.tri));
      result.unimprovable.push_back(u);
    }
    if (outcome == Outcome::Converged && !result.unimprovable.empty()) outcome = Outcome::Unimprovable;

    result.outcome = outcome;
    result.steiner_points = steiner;
    result.cocircular_ties = initial_ties + inserter_.cocircular_ties;
    populate_.finish();  // before the arrays are freed
    if (opt_.on_vertices) opt_.on_vertices(mesh_.pts, static_cast<std::size_t>(mem_.input_vertices));
    result.mesh = mesh_.take_canonical_mesh(mem_, threads_or_cores(opt_.threads));
    result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return result;
  }

 private:
  // Every order but batch: one queue, each triangle refined while it remains (section 7).
  void run_queue(std::vector<Keyed>& initial, RefineResult& result) {
    BadQueue queue(opt_.order, opt_.order_seed, mesh_);
    inserter_.record_creation = opt_.order == QueueOrder::Flip;
    queue.push(initial, true);
    Located at;  // where settle found choice's point, if it did
    while (outcome_ == Outcome::Converged && (!queue.empty() || requeue_stopped(queue))) {
      const Item item = queue.pop();
      bool first = true;
      while (still_there(mesh_, item)) {
        lepp_search(mesh_, item.tri, lepp_);
        if (!guards_pass(item, result)) break;
        prefetch_around(lepp_);
        Choice choice = select_point(mesh_, lepp_, opt_.method);  // made in place: no copy (point_selection.h)
        if (!settle(item, choice, result, &at)) break;
        const bool go_on = insert_choice(item, choice, first, result, at);
        first = false;
        queue.push(fresh_, false);
        if (!go_on) break;
      }
    }
  }

  // The batch order (section 7): rounds of triangles whose regions (Lepp, terminal
  // pair, the insertion's cavity and its ring) are apart, inserted in queue order.
  // With several threads each window of the round is looked at on all threads
  // first (round_picks.h); the members are the same.
  void run_rounds(std::vector<Keyed>& initial, RefineResult& result) {
    std::sort(initial.begin(), initial.end(), KeyLess{});
    std::vector<Item> round, next, ahead;  // ahead: the next round's queue as it is built
    for (const Keyed& k : initial) round.push_back(k.item);
    std::vector<Keyed> tails;
    std::vector<int> region, cavity;
    RoundMarks marks, queued;
    Choice choice;
    const int threads = threads_or_cores(opt_.threads);
    const std::size_t per_thread = opt_.batch_window > 0 ? static_cast<std::size_t>(opt_.batch_window) : kWindowPerThread;
    const std::size_t window = per_thread * static_cast<std::size_t>(threads);
    std::vector<std::size_t> wanted;  // the window's triangles not touched as it begins
    std::vector<Pick> picks;          // theirs, in that order
    while (outcome_ == Outcome::Converged) {
      if (round.empty()) {
        const std::vector<Keyed> again = take_stopped();
        if (again.empty()) break;
        for (const Keyed& k : again) round.push_back(k.item);
      }
      marks.begin_round();
      next.clear();
      tails.clear();
      bool closed = false;
      int members = 0;
      std::size_t looks = 0, rest = round.size();  // round[rest, ...) waits unlooked
      bool kept = false;                             // a member kept a triangle (section 6)
      bool counted = false;                          // the round has a triangle in the mesh
      std::size_t window_end = 0, k = 0;  // the window is round[..., window_end); wanted[k] comes next
      bool window_picked = false;          // its untouched triangles have picks
      for (std::size_t i = 0; i < round.size(); ++i) {
        const Item& item = round[i];
        if (outcome_ != Outcome::Converged) break;
        // A closed round, or one past its looks (kBatchLooksPerMember per member and
        // kBatchFreeLooks more: where most entries wait, as in a fan that all their
        // cavities hold, it ends early), leaves the rest of its queue as it is.
        if (closed || looks >= batch_looks_allowed(members)) {
          rest = i;
          break;
        }
        if (threads > 1 && i == window_end) {
          // No further than the looks the round has left: those it makes in any case.
          const std::size_t left = batch_looks_allowed(members) - looks;
          window_end = std::min(round.size(), i + std::min(window, left)), k = 0;
          wanted.clear();
          for (std::size_t j = i; j < window_end; ++j)
            if (still_there(mesh_, round[j]) && !marks.touched(round[j].tri)) wanted.push_back(j);
          // A window not worth the threads is looked at here, one by one.
          window_picked = threads_for(wanted.size(), threads, per_thread) > 1;
          if (window_picked) pick_window(mesh_, round, wanted, marks, opt_.method, obstacles_, threads, per_thread, picks);
        }
        if (!still_there(mesh_, item)) continue;
        // A round counts from its first triangle still in the mesh (the rest of a queue
        // moved as it is may hold none).
        if (!counted) counted = true, ++result.rounds;
        if (marks.touched(item.tri)) {
          next.push_back(item);
          continue;
        }
        ++looks, ++result.looks;
        bool plain;
        if (window_picked && i < window_end) {
          // Untouched now, so untouched as the window began: it has a pick.
          while (wanted[k] != i) ++k;
          const Pick& p = picks[k];
          bool apart = !p.waits;
          for (int ti : p.plain ? p.region : p.lepp.path) apart = apart && !marks.touched(ti);
          if (!apart) {
            next.push_back(item);
            continue;
          }
          lepp_ = p.lepp;  // (the path's vector keeps its capacity)
          choice = p.choice;
          plain = p.plain;
          if (plain) region.assign(p.region.begin(), p.region.end());
        } else {
          lepp_search(mesh_, item.tri, lepp_);
          bool apart = true;
          for (int ti : lepp_.path) apart = apart && !marks.touched(ti);
          if (!apart) {
            next.push_back(item);
            continue;
          }
          prefetch_around(lepp_);
          choice = select_point(mesh_, lepp_, opt_.method);
          plain = plain_choice(mesh_, lepp_, choice, obstacles_);
          if (plain) {
            region.assign(lepp_.path.begin(), lepp_.path.end());
            if (!cavity_and_ring(mesh_, choice, marks, region, cavity)) {
              next.push_back(item);
              continue;
            }
          }
        }
        if (plain) {
          for (int ti : region) marks.mark(ti);
          if (!guards_pass(item, result)) break;
        } else {
          // At the limit: only as the round's first member, on the round's mesh.
          if (members > 0) {
            next.push_back(item);
            continue;
          }
          if (!guards_pass(item, result)) break;
          if (!settle(item, choice, result)) continue;  // left (the precision stop): nothing changed
          closed = true;  // its alternatives read beyond any region: the round ends with it
        }
        ++members;
        const bool go_on = insert_choice(item, choice, true, result);
        mesh_.for_each_in_star(around_, [&](int ti) { marks.mark(ti); });
        if (const int k = inserter_.kept(); k >= 0) marks.mark(k), kept = true;
        std::sort(fresh_.begin(), fresh_.end(), KeyLess{});
        tails.insert(tails.end(), fresh_.begin(), fresh_.end());
        if (still_there(mesh_, item)) next.push_back(item);
        if (!go_on) break;
      }
      next_round_queue(mesh_, round, rest, next, tails, kept, queued, ahead);
      std::swap(round, ahead);
    }
  }

  // The guards before an insertion (section 9): false when one ends the run.
  bool guards_pass(const Item& item, RefineResult& result) {
    if (opt_.time_limit_seconds > 0 &&
        std::chrono::duration<double>(Clock::now() - start_).count() > opt_.time_limit_seconds) {
      outcome_ = Outcome::TimeLimit;
    } else if (steiner_ >= budget_) {
      outcome_ = Outcome::SteinerBudget;
    }
    if (outcome_ == Outcome::Converged) {
      // An insertion adds one vertex and at most two triangle slots (tri_mesh.h's splits).
      // Within the limits read as the run began (id_limits(): a test lowers them
      // before, never during, a run), check_capacity would pass: no call.
      const std::int64_t vertices = static_cast<std::int64_t>(mesh_.pts.size()) + 1,
                         triangles = static_cast<std::int64_t>(mesh_.tris.size()) + 2;
      if (!ids_fit(vertices, triangles, limits_)) check_capacity(vertices, triangles, steiner_);
      return true;
    }
    result.stuck = describe(mesh_, item, lepp_);
    return false;
  }

  // Select Point's choice for lepp_, as inserted (section 8b): false when no
  // resolution of it can be inserted (the precision stop leaves the triangle).
  // *at: where the formula's point lies, when settle_choice found it there.
  bool settle(const Item& item, Choice& choice, RefineResult& result, Located* at = nullptr) {
    if (settle_choice(mesh_, lepp_, opt_.method, choice, obstacles_, at)) return true;
    bool cut = false;
    if (!other_tie_resolution(mesh_, item.tri, opt_.method, opt_.tie_search_states, lepp_, choice, obstacles_, &cut)) {
      ++result.precision_stops;
      stopped_.push_back({item, choice.rule, choice.point, cut});
      return false;
    }
    ++result.tie_resolutions;
    return true;
  }

  // Inserts the settled choice for item, as every order does: statistics, trace,
  // the new point's batch of processed bad triangles (fresh_), the edge floor.
  // False when an edge below the floor ends the run.
  bool insert_choice(const Item& item, const Choice& choice, bool first, RefineResult& result, Located at = {}) {
    ++result.lepp_searches;
    result.lepp_triangles += static_cast<std::int64_t>(lepp_.path.size());
    if (first && sized_ && quality_.too_big(mesh_, item.tri)) ++result.area_refined;
    TraceStep step;
    if (opt_.trace) step = trace_step(item, lepp_, choice);
    int split_segment = -1;
    const int p = static_cast<int>(mesh_.pts.size());
    around_ = inserter_.insert(mesh_, mem_, choice, split_segment, at);
    if (split_segment >= 0) obstacles_.on_split(mesh_, split_segment, p);
    ++steiner_;
    if ((steiner_ & (PopulateAhead::kEvery - 1)) == 0) populate_.advance(mesh_);
    if (opt_.trace) {
      step.split_segment = split_segment;
      step.round = result.rounds;
      result.trace.push_back(std::move(step));
    }

    // The new point's star: every triangle this insertion made.
    bool below_floor = false;
    fresh_.clear();
    mesh_.for_each_in_star(around_, [&](int ti) {
      bool below = false;  // a spoke of ti (p at v[0]) below the floor
      if (quality_.processed_made(mesh_, ti, floor_, &below)) append_keyed(fresh_, mesh_, ti);
      below_floor = below_floor || below;
    });
    if (inserter_.record_creation) set_creation_ranks(fresh_);
    // A split off its line may keep a triangle beside its sliver: its edge ab is
    // no longer constrained, so it is judged again, last in creation order.
    if (const int k = inserter_.kept(); k >= 0 && quality_.processed(mesh_, k)) {
      fresh_.push_back(keyed(mesh_, k));
      fresh_.back().created = static_cast<int>(inserter_.created().size());
    }
    if (opt_.on_insertion) {
      Mesh now = mesh_.to_mesh(mem_);
      canonicalize(now);
      opt_.on_insertion(now);
    }
    if (opt_.on_progress && (steiner_ & 0xffff) == 0) opt_.on_progress(steiner_);
    // 8192 points a block: the writer's last block, formatted during the canonical
    // sort, stays small beside the run.
    if (opt_.on_vertices && (steiner_ & 0x1fff) == 0) opt_.on_vertices(mesh_.pts, static_cast<std::size_t>(mem_.input_vertices));
    if (!below_floor) return true;
    outcome_ = Outcome::EdgeFloor;
    result.stuck = describe(mesh_, item, lepp_) + fmt::format("; Steiner point {} made an edge below the floor", p);
    return false;
  }

  // A bad triangle the precision stop left: retried when the queue runs dry if
  // points were inserted since (its Lepp may have changed), listed otherwise.
  struct Stopped {
    Item item;
    Rule rule;
    Point point;
    bool cut;  // the tie search stopped at its bound
  };
  std::vector<Keyed> take_stopped() {
    std::vector<Keyed> again;
    if (steiner_ == refill_mark_ || stopped_.empty()) return again;
    refill_mark_ = steiner_;
    for (const Stopped& s : stopped_)
      if (still_there(mesh_, s.item)) again.push_back(keyed(mesh_, s.item.tri));
    stopped_.clear();
    std::sort(again.begin(), again.end(), KeyLess{});
    again.erase(std::unique(again.begin(), again.end(), [](const Keyed& x, const Keyed& y) { return !key_less(x, y) && !key_less(y, x); }),
                again.end());
    return again;
  }
  bool requeue_stopped(BadQueue& queue) {
    std::vector<Keyed> again = take_stopped();
    queue.push(again, true);  // as the initial queue (section 7's order)
    return !queue.empty();
  }

  // The flip order: each batch member's place in the insertion's creation order
  // (a star has a handful of triangles: a linear search is the cheap way).
  void set_creation_ranks(std::vector<Keyed>& batch) const {
    const std::vector<Item>& created = inserter_.created();
    for (Keyed& k : batch) {
      k.created = -1;
      for (std::size_t i = 0; i < created.size(); ++i)
        if (created[i].tri == k.item.tri && created[i].stamp == k.item.stamp) k.created = static_cast<int>(i);
      if (k.created < 0) throw std::logic_error("fast engine: a triangle of the new point's star was not created by its insertion");
    }
  }

  // The insertion's flips will read the triangles around the terminal pair:
  // start fetching them while the point is being selected. Always inlined, as
  // BadQueue::prefetch_ahead (GCC deletes calls to a pure function: a prefetch
  // does not count as an effect).
  [[gnu::always_inline]] void prefetch_around(const Lepp& lepp) const {
    for (int t : {lepp.t1, lepp.t2}) {
      if (t < 0) continue;
      __builtin_prefetch(&mesh_.stamp[static_cast<std::size_t>(t)], 1);  // the split bumps it
      const FTri& f = mesh_.t(t);
      for (int i = 0; i < 3; ++i)
        if (f.nbr[i] >= 0) __builtin_prefetch(&mesh_.t(nbr_tri(f.nbr[i])));
    }
  }

  TraceStep trace_step(const Item& item, const Lepp& lepp, const Choice& choice) const {
    TraceStep s;
    s.bad = canonical(mesh_.t(item.tri));
    for (int ti : lepp.path) s.lepp.push_back(canonical(mesh_.t(ti)));
    const FTri& f1 = mesh_.t(lepp.t1);
    int a = f1.v(next3(lepp.e1)), b = f1.v(prev3(lepp.e1));
    s.terminal_edge = {a, b};  // as t1 runs along it, counter-clockwise
    s.t1 = canonical(f1);
    if (lepp.t2 >= 0) s.t2 = canonical(mesh_.t(lepp.t2));
    s.rule = choice.rule;
    s.point = choice.point;
    return s;
  }

  const Pslg& pslg_;
  const RefineOptions& opt_;
  SegmentMembership mem_;
  Quality quality_;
  TriMesh mesh_;
  Inserter inserter_;
  // The arrays' next pages, on a second thread when there is one (after mesh_: destroyed first).
  PopulateAhead populate_{threads_or_cores(opt_.threads) > 1};
  SliverObstacles obstacles_{pslg_, mem_};  // what the sliver clause tests (section 8b)
  std::vector<Stopped> stopped_;
  std::int64_t refill_mark_ = 0;
  // The run's state between the steps of its loop.
  Outcome outcome_ = Outcome::Converged;
  std::int64_t steiner_ = 0, budget_ = 0;
  double floor_ = 0;
  Clock::time_point start_;
  bool sized_ = false;
  const IdLimits limits_ = id_limits();
  Lepp lepp_;
  std::vector<Keyed> fresh_;  // the last insertion's batch
  int around_ = -1;           // a triangle of the last insertion's star
  // The batch order's windows: this many triangles per thread (round_picks.h),
  // unless RefineOptions::batch_window says otherwise. Measured: docs/BENCHMARKS.md.
  static constexpr std::size_t kWindowPerThread = 2048;
};

}  // namespace

Mesh build_cdt(const Pslg& pslg) {
  SegmentMembership mem = make_membership(pslg);
  Mesh mesh = build_initial_cdt(pslg, mem, 0, 0).to_mesh(mem);
  canonicalize(mesh);
  return mesh;
}

RefineResult refine(const Pslg& pslg, const RefineOptions& options) { return Refiner(pslg, options).run(); }

}  // namespace lepp::fast
