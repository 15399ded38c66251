// SPDX-License-Identifier: GPL-3.0-or-later
// The deviation catalogue's diagnosis of a point that is no choice
// (Replay::diagnose): every triangle's Lepp walked, the catalogue's points
// and the paper's choices for good triangles and at 1000 times the tolerance
// tried, the first rule in catalogue order (lepp/audit/deviations.h) names it.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include <fmt/format.h>

#include "replayer.h"

namespace lepp::audit::replay_detail {
namespace {

// Each rule's nearest point so far: (distance, tolerance).
using Nearest = std::array<std::pair<double, double>, kDeviations>;
constexpr std::size_t kNearestShown = 3;

double nearest_ratio(const Nearest& nearest, int k) {
  return nearest[static_cast<std::size_t>(k)].first / nearest[static_cast<std::size_t>(k)].second;
}

// The rules shown for a point no rule names: those with a point, fewest
// tolerances away first (the lower rank on a tie), at most kNearestShown.
std::vector<int> nearest_shown(const Nearest& nearest) {
  std::vector<int> ranks;
  for (int k = 0; k < kDeviations; ++k)
    if (static_cast<Deviation>(k) != Deviation::Unknown && std::isfinite(nearest[static_cast<std::size_t>(k)].first))
      ranks.push_back(k);
  std::stable_sort(ranks.begin(), ranks.end(), [&](int a, int b) { return nearest_ratio(nearest, a) < nearest_ratio(nearest, b); });
  if (ranks.size() > kNearestShown) ranks.resize(kNearestShown);
  return ranks;
}

// Tolerances beyond which a point of rule `rank` (any rule: none) changes nothing
// shown, now or later: the last shown rule's ratio once kNearestShown rules have a
// point (a point more tolerances away than that neither enters the list nor moves
// a shown rule's nearest, and that ratio only falls), else infinity; and no more
// than the rule's own nearest ratio (a point no nearer leaves it as it is).
double shown_ratio_bound(const Nearest& nearest, std::optional<Deviation> rank) {
  const std::vector<int> ranks = nearest_shown(nearest);
  double bound = ranks.size() < kNearestShown ? std::numeric_limits<double>::infinity() : nearest_ratio(nearest, ranks.back());
  if (rank) bound = std::min(bound, nearest_ratio(nearest, static_cast<int>(*rank)));
  return bound;
}

// "; nearest rules: precision 0.01 away (1.2e+10 tolerances), ..." for the three
// rules whose points came nearest, in units of their tolerances (the first is the
// one a reader would widen or add a rule beside); "" when no rule had a point.
std::string nearest_rules_text(const Nearest& nearest) {
  std::string s;
  for (int k : nearest_shown(nearest))
    s += fmt::format("{}{} {:.3g} away ({:.3g} tolerances)", s.empty() ? "; nearest rules: " : ", ",
                     to_string(static_cast<Deviation>(k)), nearest[static_cast<std::size_t>(k)].first, nearest_ratio(nearest, k));
  return s;
}

}  // namespace

// One table (catalogue_points, triangle_points, the paper's choices for good
// triangles and at 1000 times the tolerance), one loop: the first rule in
// catalogue order with a point within its tolerance of p names it.
DeviationMatch Replayer::diagnose(const Point& p) const {
  DeviationMatch best;
  int best_rank = kDeviations;
  double best_d = std::numeric_limits<double>::infinity();
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return best;
  // Each rule's nearest point (distance, tolerance), for a point no rule names:
  // the reader sees how far it is from every rule, in units of each one's tolerance.
  Nearest nearest;
  nearest.fill({std::numeric_limits<double>::infinity(), 1.0});
  // A configuration whose every candidate (all of rule `rank`, if given) is farther
  // than its tolerance (times `factor`) neither names p nor, farther than
  // shown_ratio_bound too, changes the list: skipped before its candidates are
  // built. Once a rule named p the list is not shown: the tolerance alone decides.
  // The catalogue has both readings' centroids; the paper's choices, the rules'.
  const bool paper_area = rules.centroid == CentroidReading::Area;
  auto far = [&](const TerminalBound& b, bool area, double factor, std::optional<Deviation> rank) {
    const double ratio = best.deviation != Deviation::Unknown ? -std::numeric_limits<double>::infinity() : shown_ratio_bound(nearest, rank);
    return far_from(p, b, area, factor, ratio);
  };
  auto consider = [&](const Candidate& c, double tol, const Terminal* t, const std::vector<FH>& lepp) {
    const int rank = static_cast<int>(c.deviation);
    if (rank > best_rank) return;
    // A point out of the doubles' range (the circumcenter of a nearly flat
    // triangle) has an infinite scale: it would match every point.
    if (!std::isfinite(tol)) return;
    const double d = distance(p, c);
    auto& near = nearest[static_cast<std::size_t>(rank)];
    if (tol > 0 && d / tol < near.first / near.second) near = {d, tol};
    if (!(d <= tol) || (rank == best_rank && d >= best_d)) return;
    best_rank = rank, best_d = d;
    best.deviation = c.deviation;
    best.paper.clear();
    if (t) {
      best.where = describe(*t, c, p, lepp);
      for (const Candidate& k : paper_candidates(rules, *t)) best.paper.push_back(describe(*t, k, p, lepp));
      if (!best.paper.empty()) best.where.rule = best.paper.front().rule;
    } else {
      ReplayChoice r;
      r.bad = ccw_ids(lepp.front());
      r.lepp = {r.bad};
      r.point = rounded_point(c);
      set_distances(p, c, r);
      best.where = r;
    }
    best.where.tolerance = tol;
  };
  for (FH f : tr.cdt.finite_face_handles()) {
    if (!in_domain(f)) continue;
    const bool bad = maybe_bad(f);
    std::vector<FH> path{f};
    std::vector<std::pair<std::vector<FH>, Terminal>> ends;
    lepp_ends(f, -1, path, ends, 64);
    if (bad)
      for (const Candidate& c : triangle_points(rules, f)) consider(c, tolerance(c.scale), nullptr, path);
    for (const auto& [lepp, t] : ends) {
      const TerminalBound bound = terminal_bound(t);
      if (!bad) {
        // Good by no more than double rounding: the program's threshold rounded, not wrong.
        const Deviation good = within_rounding_of_theta(f) ? Deviation::InexactThreshold : Deviation::GoodTriangle;
        if (far(bound, paper_area, 1, good)) continue;
        for (Candidate c : paper_candidates(rules, t)) {
          c.deviation = good;
          consider(c, tolerance(c.scale), &t, lepp);
        }
        continue;
      }
      if (!far(bound, true, 1, std::nullopt))  // the catalogue's rules
        for (const Candidate& c : catalogue_points(rules, t)) consider(c, tolerance(c.scale), &t, lepp);
      if (far(bound, paper_area, 1000, Deviation::Precision)) continue;
      for (Candidate c : paper_candidates(rules, t)) {
        c.deviation = Deviation::Precision;
        consider(c, 1000 * tolerance(c.scale), &t, lepp);
      }
    }
  }
  // The paper's choices again, with the lengths' near ties as ties: only when
  // no rule before it matched (another walk of every Lepp).
  if (best_rank > static_cast<int>(Deviation::InexactLength)) {
    LengthTiesWithinRounding relaxed(true);
    for_each_bad_lepp_end([&](const std::vector<FH>& lepp, const Terminal& t) {
      if (far(terminal_bound(t), paper_area, 1, Deviation::InexactLength)) return;
      for (Candidate c : paper_candidates(rules, t)) {
        c.deviation = Deviation::InexactLength;
        consider(c, tolerance(c.scale), &t, lepp);
      }
    });
  }
  best.what = match_text(best.deviation, best.where.terminal_edge, best.where.bad);
  if (best.deviation == Deviation::Unknown) best.what += nearest_rules_text(nearest);
  return best;
}

}  // namespace lepp::audit::replay_detail
