// SPDX-License-Identifier: GPL-3.0-or-later
// The minimum-angle check on the built index, with the unimprovable rule and the two exemptions.
#include <algorithm>
#include <array>
#include <chrono>
#include <map>
#include <optional>
#include <set>
#include <string>

#include "../exact.h"
#include "../passes.h"
#include "../precision_limit.h"
#include "../ranges.h"
#include "../small_input_angles_internal.h"
#include "lepp/angle.h"
#include "lepp/certify/checks.h"
#include "lepp/stats.h"
#include "small_angle_exemption.h"

namespace lepp::certify {
namespace pass {
namespace {

PrecisionView precision_view(const MeshIndex& ix) {
  return {ix.mesh, ix.tri_ok, ix.twin, ix.constrained_half, ix.outside, ix.chain_segments};
}

// The segments mesh vertex v lies on: an input vertex's own, a Steiner vertex's chain.
std::vector<int> segments_of(const MeshIndex& ix, int v) {
  std::vector<int> out;
  const int in = ix.mesh_to_input[static_cast<std::size_t>(v)];
  if (in >= 0) {
    for (std::size_t s = 0; s < ix.pslg.segments.size(); ++s)
      if (ix.pslg.segments[s].a == in || ix.pslg.segments[s].b == in) out.push_back(static_cast<int>(s));
  } else if (ix.vertex_segment[static_cast<std::size_t>(v)] >= 0) {
    out.push_back(ix.vertex_segment[static_cast<std::size_t>(v)]);
  }
  return out;
}

// Triangles of a witness's Lepp named in its text, at each end (the JSON has them all):
// a Lepp along a strip at the limit runs through thousands.
constexpr std::size_t kWitnessLeppEnds = 3;

// The witness of a rejected claim, one clause: the point with its exact value (the
// shortest decimal that reads back to it, and hexadecimal), the branch and the choice
// that reach it (the Lepp under one resolution of exact length ties).
std::string witness_text(const PrecisionWitness& w) {
  auto edge = [](const std::array<int, 2>& e) { return fmt::format("{}-{}", e[0], e[1]); };
  std::string lepp;
  const std::size_t n = w.lepp.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (i == kWitnessLeppEnds && n > 2 * kWitnessLeppEnds + 1) {
      lepp += fmt::format(" -> ... {} more triangles ...", n - 2 * kWitnessLeppEnds);
      i = n - kWitnessLeppEnds - 1;
      continue;
    }
    lepp += fmt::format("{}triangle {} (longest {})", i ? " -> " : "", w.lepp[i], edge(w.longest[i]));
  }
  std::string choice = w.terminal_other >= 0 ? fmt::format(", terminal pair with triangle {}", w.terminal_other) : std::string();
  if (w.second1[0] >= 0) choice += fmt::format(", second-longest edges {} and {}", edge(w.second1), edge(w.second2));
  if (w.split[0] >= 0) choice += fmt::format(", splitting edge {}", edge(w.split));
  return fmt::format("witness point ({}, {}) = ({:a}, {:a}), rounding {}, branch {}: Lepp {}{}", w.point.x, w.point.y, w.point.x,
                     w.point.y, w.rounding, to_string(w.rule), lepp, choice);
}

std::string undecided_text(const PrecisionClaim& c, const Options& o) {
  switch (c.undecided) {
    case PrecisionUndecided::Bound: return fmt::format("at bound {} Lepp states", o.tie_search_states);
    case PrecisionUndecided::TimeLimit: return fmt::format("at the time limit of {} s, after {} Lepp states", o.time_limit_seconds, c.states);
    case PrecisionUndecided::BadMesh: return "at a bad triangle or edge";
  }
  return "";
}

// ALGORITHM.md section 8, checked on the mesh itself.
bool unimprovable_rule_holds(const MeshIndex& ix, std::size_t t, double s_hi) {
  const int shortest_half = [&] {
    int best = 0;
    for (int i = 1; i < 3; ++i) {
      const int h = static_cast<int>(3 * t) + i, b = static_cast<int>(3 * t) + best;
      if (ix.longer(ix.from(b), ix.to(b), ix.from(h), ix.to(h))) best = i;
    }
    return static_cast<int>(3 * t) + best;
  }();
  const int p = ix.from(shortest_half), q = ix.to(shortest_half);
  const int r = ix.T(t)[static_cast<std::size_t>((shortest_half % 3 + 2) % 3)];
  for (int s1 : segments_of(ix, p))
    for (int s2 : segments_of(ix, q)) {
      if (s1 == s2) continue;
      const Segment &x = ix.pslg.segments[static_cast<std::size_t>(s1)], &y = ix.pslg.segments[static_cast<std::size_t>(s2)];
      for (int v_in : {x.a, x.b}) {
        if (v_in != y.a && v_in != y.b) continue;
        const int v = ix.input_to_mesh[static_cast<std::size_t>(v_in)];
        if (v < 0 || v == p || v == q) continue;
        const Point& V = ix.pslg.vertices[static_cast<std::size_t>(v_in)];
        const Point& U = ix.pslg.vertices[static_cast<std::size_t>(x.a == v_in ? x.b : x.a)];
        const Point& W = ix.pslg.vertices[static_cast<std::size_t>(y.a == v_in ? y.b : y.a)];
        // Inside the wedge: the third vertex on s1 or s2, or in the closed sector at v between them.
        const std::vector<int> on = segments_of(ix, r);
        if (std::find(on.begin(), on.end(), s1) == on.end() && std::find(on.begin(), on.end(), s2) == on.end()) {
          const int sigma = exact::orient(V, U, W);
          if (exact::orient(V, U, ix.P(r)) * sigma < 0 || exact::orient(V, ix.P(r), W) * sigma < 0) continue;
        }
        if (exact::acute_angle_sin2_below(V, U, W, s_hi)) return true;
      }
    }
  return false;
}

void check_angles(Certification& cert) {
  const MeshIndex& ix = cert.index;
  const Sin2Bracket bracket = sin2_bracket(cert.options.min_angle_deg);
  auto sorted = [](Tri x) {
    std::sort(x.begin(), x.end());
    return x;
  };
  std::map<Tri, std::size_t> listed;  // sorted triple -> index in options.unimprovable
  for (std::size_t i = 0; i < cert.options.unimprovable.size(); ++i) listed.emplace(sorted(cert.options.unimprovable[i].triangle), i);
  std::vector<char> found(cert.options.unimprovable.size(), 0);
  PrecisionLimits limits;
  limits.states = cert.options.tie_search_states;
  limits.ties_by_ids = cert.options.precision_ties_by_ids;
  if (cert.options.time_limit_seconds > 0)
    limits.deadline = std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                             std::chrono::duration<double>(cert.options.time_limit_seconds));
  cert.report.tie_search_states = cert.options.tie_search_states;
  cert.report.time_limit_seconds = cert.options.time_limit_seconds;
  // The triangles with an angle below theta, found with the index (index_triangles, over
  // ranges: the exact signs are the search's cost); what follows, in triangle order on
  // this thread, sees only those.
  for (const std::vector<MeshIndex::BelowTheta>& in_range : ix.below_theta)
    for (const auto& [t, worst, certainly] : in_range) {
      const Tri& x = ix.T(t);
      // Decided before the engine's list is looked at: the rule sees only input and mesh.
      const int exempt = cert.options.exempt_small_input_angles ? exempting_angle(ix, cert.report.small_angles, t) : -1;
      if (exempt >= 0) {
        cert.report.exempt_triangles.push_back(static_cast<int>(t));
        cert.report.exempt_angle.push_back(exempt);
      }
      // The precision limit (section 5c), likewise from input and mesh alone.
      std::optional<PrecisionClaim> searched;  // kept for a listed claim below: the search is not run twice
      if (exempt < 0 && cert.options.exempt_precision_limited)
        searched = precision_claim(precision_view(ix), t, cert.options.precision_method, limits);
      const bool limited = searched && searched->outcome == PrecisionOutcome::Exempt;
      if (limited) cert.report.precision_exempt_triangles.push_back(static_cast<int>(t));
      auto it = listed.find(sorted(x));
      if (it != listed.end()) {
        const std::size_t listed_index = it->second;
        found[listed_index] = 1;
        if (cert.options.unimprovable[listed_index].reason == LeftReason::DoublePrecision) {
          const PrecisionClaim claim =
              searched ? *searched : precision_claim(precision_view(ix), t, cert.options.precision_method, limits);
          cert.report.precision_claims.push_back(claim);
          if (claim.outcome == PrecisionOutcome::Exempt) {
            cert.report.unimprovable_accepted.push_back(cert.options.unimprovable[listed_index]);
            continue;
          }
          // Undecided: the claim cannot be verified, so it is not accepted; the text says which.
          if (claim.outcome == PrecisionOutcome::Undecided) ++cert.report.precision_undecided;
          cert.add({Reason::UnimprovableRuleFails,
                    claim.outcome == PrecisionOutcome::Rejected
                        ? fmt::format("{} is listed as limited by double precision but a point Select Point ({}) allows for it, as "
                                      "rounded, can be inserted: {}",
                                      ix.tri_text(t), to_string(cert.options.precision_method), witness_text(claim.witness))
                        : fmt::format("{} is listed as limited by double precision but the search of its Lepps under every "
                                      "resolution of exact length ties stopped undecided {}, so the claim is not verified",
                                      ix.tri_text(t), undecided_text(claim, cert.options)),
                    {static_cast<int>(t)}, {}, {x[0], x[1], x[2]}, {}, -1});
          continue;
        }
        if (unimprovable_rule_holds(ix, t, bracket.hi)) {
          cert.report.unimprovable_accepted.push_back(cert.options.unimprovable[listed_index]);
          continue;
        }
        cert.add({Reason::UnimprovableRuleFails,
                  fmt::format("{} is listed unimprovable but its shortest edge does not join two segments meeting at an input angle below {}",
                              ix.tri_text(t), cert.options.min_angle_deg),
                  {static_cast<int>(t)}, {}, {x[0], x[1], x[2]}, {}, -1});
        continue;
      }
      if (exempt >= 0 || limited) continue;
      const double deg = min_angle_deg(ix.P(x[0]), ix.P(x[1]), ix.P(x[2]));
      cert.add({certainly ? Reason::AngleBelowTheta : Reason::AngleNotCertified,
                fmt::format("{} has an angle at vertex {} {} theta = {} (about {} degrees)", ix.tri_text(t), x[static_cast<std::size_t>(worst)],
                            certainly ? "below" : "within one ulp of", cert.options.min_angle_deg, deg),
                {static_cast<int>(t)}, {}, {x[0], x[1], x[2]}, {}, -1});
    }
  cert.report.exempt_count = cert.report.exempt_triangles.size();
  cert.report.precision_exempt_count = cert.report.precision_exempt_triangles.size();
  // Listed but not skinny is harmless for the angle check; listed but absent is not.
  std::set<Tri> triangles;
  if (std::find(found.begin(), found.end(), 0) != found.end())
    for (std::size_t t = 0; t < ix.mesh.triangles.size(); ++t) triangles.insert(sorted(ix.T(t)));
  for (std::size_t i = 0; i < cert.options.unimprovable.size(); ++i) {
    const Tri& x = cert.options.unimprovable[i].triangle;
    if (!found[i] && !triangles.count(sorted(x)))
      cert.add({Reason::UnimprovableNotInMesh,
                fmt::format("listed unimprovable triangle {} {} {} is not a triangle of the mesh", x[0], x[1], x[2]), {}, {}, {}, {}, -1});
  }
}

}  // namespace

void min_angle(Certification& cert) {
  if (cert.options.exempt_small_input_angles) cert.report.small_angles = small_input_angles(cert.index.pslg, cert.index.domain);
  if (cert.options.min_angle_deg > 0) check_angles(cert);
}

}  // namespace pass

Report check_min_angle(const Pslg& pslg, const Mesh& mesh, const Options& options) {
  return pass::run_alone(Check::MinAngle, pass::min_angle, pslg, mesh, options);
}

}  // namespace lepp::certify
