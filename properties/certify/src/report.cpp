// SPDX-License-Identifier: GPL-3.0-or-later
// Names of checks and reasons, the verdict, and the human-readable report.
#include <algorithm>
#include <string>

#include <fmt/format.h>

#include "lepp/certify.h"

namespace lepp::certify {

Check check_of(Reason reason) {
  switch (reason) {
    case Reason::BadTriangle:
    case Reason::NotCounterClockwise:
    case Reason::DuplicateMeshVertex:
    case Reason::EdgeOverused:
    case Reason::EdgeSameDirection:
    case Reason::UnusedVertex:
    case Reason::BoundaryNotOnDomainBoundary:
    case Reason::MeshOutsideDomain:
    case Reason::DomainBoundaryUncovered:
    case Reason::ChainEdgesMeet:
    case Reason::EulerCharacteristic: return Check::Topology;
    case Reason::InputVertexMissing:
    case Reason::InputVertexMoved: return Check::InputVertices;
    case Reason::SegmentMissing:
    case Reason::SteinerOffSegment:
    case Reason::ConstrainedEdgeNotOnSegment:
    case Reason::ConstrainedEdgeUnlisted:
    case Reason::ConstrainedEdgeWrongSegment: return Check::Constraints;
    case Reason::NotLocallyDelaunay: return Check::Delaunay;
    case Reason::AngleBelowTheta:
    case Reason::AngleNotCertified:
    case Reason::UnimprovableNotInMesh:
    case Reason::UnimprovableRuleFails: return Check::MinAngle;
    case Reason::TerminalAngleOver120: return Check::Theorem2;
    case Reason::AreaAboveBound: return Check::SizeBound;
  }
  return Check::Topology;
}

const char* to_string(Check check) {
  switch (check) {
    case Check::Topology: return "topology";
    case Check::InputVertices: return "input-vertices";
    case Check::Constraints: return "constrained-edges";
    case Check::Delaunay: return "delaunay";
    case Check::MinAngle: return "min-angle";
    case Check::Theorem2: return "theorem-2";
    case Check::SizeBound: return "size-bound";
  }
  return "?";
}

const char* to_string(Reason reason) {
  switch (reason) {
    case Reason::BadTriangle: return "bad-triangle";
    case Reason::NotCounterClockwise: return "not-counter-clockwise";
    case Reason::DuplicateMeshVertex: return "duplicate-mesh-vertex";
    case Reason::EdgeOverused: return "edge-overused";
    case Reason::EdgeSameDirection: return "edge-same-direction";
    case Reason::UnusedVertex: return "unused-vertex";
    case Reason::BoundaryNotOnDomainBoundary: return "boundary-not-on-domain-boundary";
    case Reason::MeshOutsideDomain: return "mesh-outside-domain";
    case Reason::DomainBoundaryUncovered: return "domain-boundary-uncovered";
    case Reason::ChainEdgesMeet: return "chain-edges-meet";
    case Reason::EulerCharacteristic: return "euler-characteristic";
    case Reason::InputVertexMissing: return "input-vertex-missing";
    case Reason::InputVertexMoved: return "input-vertex-moved";
    case Reason::SegmentMissing: return "segment-missing";
    case Reason::SteinerOffSegment: return "steiner-off-segment";
    case Reason::ConstrainedEdgeNotOnSegment: return "constrained-edge-not-on-segment";
    case Reason::ConstrainedEdgeUnlisted: return "constrained-edge-unlisted";
    case Reason::ConstrainedEdgeWrongSegment: return "constrained-edge-wrong-segment";
    case Reason::NotLocallyDelaunay: return "not-locally-delaunay";
    case Reason::AngleBelowTheta: return "angle-below-theta";
    case Reason::AngleNotCertified: return "angle-not-certified";
    case Reason::UnimprovableNotInMesh: return "unimprovable-not-in-mesh";
    case Reason::UnimprovableRuleFails: return "unimprovable-rule-fails";
    case Reason::TerminalAngleOver120: return "terminal-angle-over-120";
    case Reason::AreaAboveBound: return "area-above-bound";
  }
  return "?";
}

const char* to_string(RegionPlace place) {
  switch (place) {
    case RegionPlace::Floods: return "floods";
    case RegionPlace::OnVertex: return "on-vertex";
    case RegionPlace::OnSegment: return "on-segment";
    case RegionPlace::Outside: return "outside";
    case RegionPlace::InHole: return "in-hole";
  }
  return "?";
}

const char* to_string(PrecisionOutcome outcome) {
  switch (outcome) {
    case PrecisionOutcome::Exempt: return "exempt";
    case PrecisionOutcome::Rejected: return "rejected";
    case PrecisionOutcome::Undecided: return "undecided";
  }
  return "?";
}

const char* to_string(PrecisionUndecided why) {
  switch (why) {
    case PrecisionUndecided::Bound: return "bound";
    case PrecisionUndecided::TimeLimit: return "time-limit";
    case PrecisionUndecided::BadMesh: return "bad-mesh";
  }
  return "?";
}

bool Report::certified() const {
  for (std::size_t c : count_by_reason)
    if (c) return false;
  return true;
}

std::size_t Report::count(Reason reason) const {
  const auto r = static_cast<std::size_t>(reason);
  return r < count_by_reason.size() ? count_by_reason[r] : 0;
}

namespace {
constexpr std::size_t kListedExempt = 10;  // exempt triangles named in the text report; all are counted
constexpr std::size_t kListedRegions = 10;  // regions named in the text report; all are counted
}  // namespace

std::string format_report(const Report& report) {
  const Statistics& s = report.stats;
  std::string out;
  std::size_t total = 0;
  for (std::size_t c : report.count_by_reason) total += c;
  out += report.certified() ? "CERTIFIED\n" : fmt::format("NOT CERTIFIED: {} violations\n", total);
  out += fmt::format("vertices {}  triangles {}  edges {}  euler {} (domain {})\n", s.vertices, s.triangles, s.edges, s.euler_mesh,
                     s.euler_domain);
  out += fmt::format("min angle {:.4f} deg  avg min angle {:.4f} deg  min area quality {:.4f}\n", s.min_angle_deg, s.avg_min_angle_deg,
                     s.min_area_quality);
  out += fmt::format("shortest edge {:.6g} ({:.6g} x shortest input segment)  avg Lepp size {:.4f}\n", s.shortest_edge,
                     s.shortest_edge_ratio, s.avg_lepp_size);
  out += fmt::format("checked: {} in-circle tests ({} cocircular), {} constrained edges, {} terminal pairs (Theorem 2){}\n",
                     s.delaunay_edges_checked, s.cocircular_edges, s.constrained_edges, s.terminal_pairs_checked,
                     report.min_angle_deg > 0 ? fmt::format(", min angle >= {}", report.min_angle_deg) : std::string());
  for (const std::string& w : report.warnings) out += fmt::format("warning: {}\n", w);
  if (!report.unimprovable_accepted.empty()) {
    std::size_t precision = 0;
    for (const UnimprovableTriangle& u : report.unimprovable_accepted) precision += u.reason == LeftReason::DoublePrecision;
    out += fmt::format("{} triangles below theta accepted as unimprovable ({} small input angle, {} double precision; rule holds)\n",
                       report.unimprovable_accepted.size(), report.unimprovable_accepted.size() - precision, precision);
  }
  if (!report.precision_claims.empty()) {
    std::size_t by[3] = {0, 0, 0};
    for (const PrecisionClaim& c : report.precision_claims) ++by[static_cast<int>(c.outcome)];
    out += fmt::format("{} triangles listed at double precision: {} exempt, {} rejected (witness below), {} undecided {}{}\n",
                       report.precision_claims.size(), by[0], by[1], by[2],
                       report.tie_search_states == 0 ? std::string("(no bound)")
                                                     : fmt::format("at bound {} Lepp states", report.tie_search_states),
                       report.time_limit_seconds > 0 ? fmt::format(" (time limit {} s)", report.time_limit_seconds) : std::string());
  }
  if (report.precision_exempt_count > 0) {
    out += fmt::format("{} triangles below theta exempt (precision limit: no point Select Point allows can be inserted as rounded)\n",
                       report.precision_exempt_count);
    const std::size_t listed = std::min(report.precision_exempt_triangles.size(), kListedExempt);
    for (std::size_t i = 0; i < listed; ++i) out += fmt::format("  exempt: triangle {} (double precision)\n", report.precision_exempt_triangles[i]);
    if (listed < report.precision_exempt_triangles.size())
      out += fmt::format("  ... and {} more exempt triangles\n", report.precision_exempt_triangles.size() - listed);
  }
  if (report.exempt_count > 0) {
    out += fmt::format("{} triangles below theta exempt (small-input-angle rule: shortest edge near an input angle below 60 deg)\n",
                       report.exempt_count);
    const std::size_t listed = std::min(report.exempt_triangles.size(), kListedExempt);
    for (std::size_t i = 0; i < listed; ++i) {
      const SmallInputAngle& a = report.small_angles[static_cast<std::size_t>(report.exempt_angle[i])];
      out += fmt::format("  exempt: triangle {} (input angle {:.4g} deg at input vertex {}, segments {} and {}, radius {:.6g})\n",
                         report.exempt_triangles[i], a.angle_deg, a.apex, a.segment1, a.segment2, a.radius);
    }
    if (listed < report.exempt_triangles.size())
      out += fmt::format("  ... and {} more exempt triangles\n", report.exempt_triangles.size() - listed);
  }
  if (report.max_area > 0 || report.region_area_bounds) {
    out += fmt::format("size bound: {} triangles checked{}{}\n", report.area_checked,
                       report.max_area > 0 ? fmt::format(", area <= {} everywhere", report.max_area) : std::string(),
                       report.region_area_bounds ? fmt::format(", the bounds of {} regions", report.region_places.size()) : std::string());
    const std::size_t listed = std::min(report.region_places.size(), kListedRegions);
    for (std::size_t r = 0; r < listed; ++r)
      out += report.region_places[r] == RegionPlace::Floods
                 ? fmt::format("  region {}: {} triangles\n", r, report.region_triangles[r])
                 : fmt::format("  region {}: {}, applies to nothing\n", r, to_string(report.region_places[r]));
    if (listed < report.region_places.size())
      out += fmt::format("  ... and {} more regions\n", report.region_places.size() - listed);
  }
  for (std::size_t r = 0; r < report.count_by_reason.size(); ++r)
    if (report.count_by_reason[r])
      out += fmt::format("  {} x {} ({})\n", report.count_by_reason[r], to_string(static_cast<Reason>(r)),
                         to_string(check_of(static_cast<Reason>(r))));
  for (const Violation& v : report.violations) out += fmt::format("{}: {}\n", to_string(v.reason), v.message);
  return out;
}

}  // namespace lepp::certify
