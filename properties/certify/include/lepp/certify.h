// SPDX-License-Identifier: GPL-3.0-or-later
// The exact certifier: decides whether a mesh is a correct (constrained)
// Delaunay quality triangulation of a PSLG, with exact predicates on the double
// coordinates. Works on any mesher's output (Triangle format), not only ours.
// docs/CERTIFIER.md gives the exact test behind every check.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "lepp/mesh.h"
#include "lepp/pslg.h"
#include "lepp/refine.h"
#include "lepp/small_input_angles.h"

namespace lepp::certify {

// The seven groups of checks.
enum class Check { Topology, InputVertices, Constraints, Delaunay, MinAngle, Theorem2, SizeBound };

// Why a check failed: one value per distinct failure, so tests can assert the reason.
enum class Reason {
  // Topology
  BadTriangle,               // a vertex id out of range or repeated in one triangle, or a non-finite coordinate
  NotCounterClockwise,       // orientation <= 0 (clockwise or degenerate)
  DuplicateMeshVertex,       // two mesh vertices with identical coordinates
  EdgeOverused,              // an edge in more than two triangles (overlap)
  EdgeSameDirection,         // two triangles traverse an edge the same way (overlap or fold)
  UnusedVertex,              // a Steiner vertex, or an input vertex inside the domain, in no triangle
  BoundaryNotOnDomainBoundary,  // a mesh boundary edge inside the domain (gap) or facing the wrong way
  MeshOutsideDomain,         // a triangle beyond a domain boundary segment (exterior or hole meshed)
  DomainBoundaryUncovered,   // a domain boundary segment with no triangle along it
  ChainEdgesMeet,            // two segment-chain edges cross or overlap, or a mesh vertex lies on one (overlap)
  EulerCharacteristic,       // V - E + F differs from the domain's
  // Input preservation
  InputVertexMissing,        // an input vertex in the domain is not a mesh vertex
  InputVertexMoved,          // mesh vertex i (i < input_vertices) differs from input vertex i
  // Constrained edges
  SegmentMissing,            // no chain of mesh edges from one endpoint of a segment to the other
  SteinerOffSegment,         // a chain vertex farther from its segment than the tolerance
  ConstrainedEdgeNotOnSegment,  // a mesh-listed constrained edge lies on no input segment chain
  ConstrainedEdgeUnlisted,   // a chain edge the mesh does not list as constrained
  ConstrainedEdgeWrongSegment,  // a listed edge tagged with another segment id than its chain's
  // Delaunay
  NotLocallyDelaunay,        // the opposite vertex strictly inside the circumcircle
  // Minimum angle
  AngleBelowTheta,           // sin^2(angle) < sin2_bracket(theta).lo: certainly below theta
  AngleNotCertified,         // lo <= sin^2(angle) < hi: within one ulp of theta, not certified
  UnimprovableNotInMesh,     // a listed unimprovable triangle is not a mesh triangle
  UnimprovableRuleFails,     // a listed unimprovable triangle does not satisfy ALGORITHM.md section 8
  // Theorem 2
  TerminalAngleOver120,      // a terminal triangle of an unconstrained terminal edge with an angle > 120 degrees
  // Size bound
  AreaAboveBound,            // a triangle's area exceeds the bound of its region or the global bound (exactly)
};

// Where a region point of the input lies (decided on the input alone, docs/CERTIFIER.md
// section 7): only a point inside the domain, off every segment and input vertex, floods.
enum class RegionPlace { Floods, OnVertex, OnSegment, Outside, InHole };

Check check_of(Reason reason);
const char* to_string(Check check);
const char* to_string(Reason reason);
const char* to_string(RegionPlace place);

// One violation: what failed, and the triangles, edges, vertices and coordinates involved.
struct Violation {
  Reason reason{};
  std::string message;                     // one line, with ids (0-based) and coordinates
  std::vector<int> triangles;              // indices into Mesh::triangles
  std::vector<std::array<int, 2>> edges;   // mesh vertex ids
  std::vector<int> vertices;               // mesh vertex ids (input ids for missing input vertices)
  std::vector<Point> points;               // coordinates of the vertices above
  int segment = -1;                        // input segment id when one is involved
  int region = -1;                         // input region id (index into Pslg::regions) when one is involved
};

struct Options {
  double min_angle_deg = 0;   // 0: no angle check
  bool conforming = false;    // every edge locally Delaunay, constrained ones too
  bool theorem2 = true;       // check Theorem 2 on every unconstrained terminal edge
  // Triangles the engine reported unimprovable (ALGORITHM.md section 8): exempt from
  // the angle check when the rule holds for them, listed apart in the report.
  std::vector<UnimprovableTriangle> unimprovable;
  // The small-input-angle exemption rule for any mesher (docs/CERTIFIER.md): a triangle
  // below theta whose shortest edge lies in the region of influence of an input angle
  // below 60 degrees is exempt, counted apart (Report::exempt_triangles), not a violation.
  // Depends only on the input and the mesh, never on lists the mesher wrote.
  bool exempt_small_input_angles = false;
  // The precision-limit exemption for any mesher (docs/CERTIFIER.md section 5c): a
  // triangle below theta every point of whose Select Point (precision_method), as
  // rounded in every way, cannot be inserted is exempt, counted apart
  // (Report::precision_exempt_triangles). Input and mesh only, like the rule above;
  // triangles listed in `unimprovable` as DoublePrecision are held to it either way.
  bool exempt_precision_limited = false;
  Method precision_method = Method::Centroid;
  // Equal edge lengths decided by mesh vertex ids as lepp's edge order does (ALGORITHM.md
  // section 3) instead of every resolution: not a certificate for another mesher (it reads
  // numbering); it tells a triangle lepp leaves because of its tie rule from one no tie
  // rule could refine (docs/CERTIFIER.md section 5c, "Finding").
  bool precision_ties_by_ids = false;
  // The bound of that search (section 5c): Lepp states per triangle, by default the
  // engines' (lepp::kTieSearchStates); 0: no bound, the search decides (it visits each
  // state once) or runs until time_limit_seconds. Beyond it, no exemption: a listed
  // claim is undecided at this bound.
  std::size_t tie_search_states = kTieSearchStates;
  // Wall-clock seconds for the precision searches of one certificate in all (0: no
  // limit): a search still running then, and every later one, stops undecided.
  double time_limit_seconds = 0;
  // Size bounds (docs/CERTIFIER.md section 7), as lepp refine's --max-area and
  // --region-areas (Triangle's -a X and -a): every triangle's area must be at most
  // max_area (> 0), and with region_area_bounds at most the bound (> 0) of the
  // region it lies in, found by flooding the mesh from the region points; with
  // both, the smaller bound applies.
  double max_area = 0;
  bool region_area_bounds = false;
  std::size_t max_listed_per_reason = 50;  // further violations are counted, not listed
  // Threads for the passes over triangles and edges (0: the machine's cores). Each pass
  // splits its work into fixed ranges and adds their violations in range order, so the
  // report is the same for any count (docs/CERTIFIER.md, "Threads").
  int threads = 1;
};

// What the certificate says of a triangle listed as left at double precision
// (ALGORITHM.md section 8b; docs/CERTIFIER.md section 5c): exempt (proved: no choice
// under any resolution of exact length ties can be inserted, at any rounding),
// rejected (a witness: one that can), or undecided (the search stopped first).
enum class PrecisionOutcome { Exempt, Rejected, Undecided };
// Why a search stopped undecided: its bound of Lepp states, the time limit, or a bad
// triangle or edge met on the way (no choice can be judged there).
enum class PrecisionUndecided { Bound, TimeLimit, BadMesh };
const char* to_string(PrecisionOutcome outcome);
const char* to_string(PrecisionUndecided why);

// A point that can be inserted, and the choice that reaches it: the Lepp under one
// resolution of exact length ties (each triangle with the edge taken as its longest,
// the listed triangle first, the terminal edge last; a second terminal triangle across
// it), the second-longest edges taken, the branch of Select Point, the edge the point
// splits (a midpoint of a constrained edge) and the rounding. Mesh vertex ids.
struct PrecisionWitness {
  Point point;                              // the double that can be inserted
  std::string rounding;                     // "formula" (the engines' double), or each coordinate "down", "up" or "exact"
  Rule rule = Rule::QuadCentroid;           // the branch
  std::vector<int> lepp;                    // triangles (indices into Mesh::triangles)
  std::vector<std::array<int, 2>> longest;  // the edge taken as longest in each of the path's triangles
  int terminal_other = -1;                  // the triangle across the terminal edge (-1: a constrained one)
  std::array<int, 2> second1{{-1, -1}}, second2{{-1, -1}};  // of the path's last triangle and terminal_other (-1: none)
  std::array<int, 2> split{{-1, -1}};       // the edge whose midpoint it is (-1: a centroid, or a located midpoint)
};

struct PrecisionClaim {
  int triangle = -1;  // index into Mesh::triangles
  PrecisionOutcome outcome = PrecisionOutcome::Undecided;
  PrecisionUndecided undecided = PrecisionUndecided::Bound;  // Undecided: why
  std::size_t states = 0;                                     // Lepp states the search visited
  PrecisionWitness witness;                                   // Rejected
};

// The statistics the paper plots (doubles, for display) and what was checked.
struct Statistics {
  std::size_t vertices = 0, triangles = 0, edges = 0;
  double min_angle_deg = 0, avg_min_angle_deg = 0, min_area_quality = 0;
  double shortest_edge = 0, shortest_edge_ratio = 0;  // shortest mesh edge, and / shortest input segment
  double avg_lepp_size = 0;                           // over every triangle, terminal triangles included
  std::size_t delaunay_edges_checked = 0;             // in-circle tests made
  std::size_t constrained_edges = 0;                  // edges on input segment chains
  std::size_t terminal_pairs_checked = 0;             // unconstrained terminal edges (Theorem 2)
  std::size_t cocircular_edges = 0;                   // in-circle exactly zero (allowed)
  long euler_mesh = 0, euler_domain = 0;
};

struct Report {
  std::vector<Violation> violations;         // at most max_listed_per_reason per reason
  std::vector<std::size_t> count_by_reason;  // every violation counted, indexed by Reason
  std::vector<UnimprovableTriangle> unimprovable_accepted;  // listed by the engine, rule holds
  // With Options::exempt_small_input_angles: the small input angles of the input, and the
  // triangles below theta the exemption rule exempts (indices into Mesh::triangles, in
  // order), each with the index in small_angles of the angle that exempts it.
  std::vector<SmallInputAngle> small_angles;
  std::vector<int> exempt_triangles;
  std::vector<int> exempt_angle;
  std::size_t exempt_count = 0;
  // With Options::exempt_precision_limited: the triangles below theta exempt as
  // limited by double precision (indices into Mesh::triangles, in order).
  std::vector<int> precision_exempt_triangles;
  std::size_t precision_exempt_count = 0;
  // Of the unimprovable-rule-fails violations, the claims of double precision whose
  // search of every tie resolution stopped undecided (CERTIFIER.md section 5c): not
  // verified, so not accepted, but no insertable point was found either.
  std::size_t precision_undecided = 0;
  // Every triangle the mesher listed as left at double precision, with the outcome
  // (in mesh order; a rejected claim's violation text has its witness), and the
  // bound and time limit the searches ran under (Options).
  std::vector<PrecisionClaim> precision_claims;
  std::size_t tie_search_states = 0;
  double time_limit_seconds = 0;
  Statistics stats;
  // Not violations: each unused exact duplicate of an input vertex merged into the
  // copy the triangles use (as Triangle's .node keeps an input's repeated vertex).
  std::vector<std::string> warnings;
  double min_angle_deg = 0;  // the theta checked (0: none)
  // The size bounds checked (Options::max_area, Options::region_area_bounds) and, with
  // region bounds, per region: where its point lies, how many triangles it kept after
  // later regions overwrote it; per mesh triangle: its region (-1 none).
  double max_area = 0;
  bool region_area_bounds = false;
  std::size_t area_checked = 0;  // triangles that had a bound, compared exactly
  std::vector<RegionPlace> region_places;
  std::vector<std::size_t> region_triangles;
  std::vector<int> triangle_region;

  bool certified() const;
  std::size_t count(Reason reason) const;
  bool has(Reason reason) const { return count(reason) > 0; }
};

// The exact certificate. pslg must be validated (lepp::validate). Mesh vertex ids
// need not equal input ids (input vertices are found by their coordinates) unless
// mesh.input_vertices > 0, which promises that they do.
Report certify(const Pslg& pslg, const Mesh& mesh, const Options& options = {});

// A human-readable report: verdict, statistics, each violation on one line.
std::string format_report(const Report& report);

// The tolerance of constrained-edge preservation (docs/CERTIFIER.md): a chain vertex P
// of segment AB with k interior vertices passes iff
//   |cross(B - A, P - A)| <= (k + 1) * ulp(M) * (|B.x - A.x| + |B.y - A.y|),
// M = the largest |coordinate| of A and B, ulp(M) = 2^(exponent(M) - 52); i.e. P is
// within (k + 1) ulp(M) per coordinate of the line AB. Exposed for tests.
double segment_tolerance(const Point& a, const Point& b, std::size_t interior_vertices);

}  // namespace lepp::certify
