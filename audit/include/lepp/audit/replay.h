// SPDX-License-Identifier: GPL-3.0-or-later
// Replays a list of Steiner points on the exact reference's mesh (CGAL CDT on
// Epeck) and says, before each insertion, which of the paper's choices the
// point is, or which deviation of the catalogue: the stepping API behind the
// conformance check (lepp/audit/judge/conformance.h). Every decision is exact; only
// the point tolerance is measured in doubles.
#pragma once
#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "lepp/audit/deviations.h"
#include "lepp/mesh.h"
#include "lepp/pslg.h"
#include "lepp/refine.h"

namespace lepp::audit {

// How "the centroid of the quad" is read: the paper's, the average of the
// four vertices (A+B+C+D)/4 as in the proof of Lemma 11, or the quad's area
// centroid (its centre of mass), which a user may declare (`--centroid area`).
enum class CentroidReading { Vertex, Area };
const char* to_string(CentroidReading reading);  // "vertex", "area"

// Which mesh the replay keeps between steps (docs/CONFORMANCE.md, "The program's
// mesh"): the exact constrained Delaunay one (the paper's), or the one a program
// whose output shows its arithmetic had. NoFlips: every point inserted without
// Lawson flips (missing-flips); NoFlipsButSplits: none after a point inserted in
// a face, the exact ones after a constrained edge's split (a program that splits
// with its library's Delaunay insertion). DoubleIncircle: Lawson flips decided by
// the in-circle determinant evaluated in double (inexact-incircle). FloatPoints:
// the point tolerance in float units, and each point inserted where the exact
// choice it matched lies, not at the float the program wrote (single-precision).
// TiesKept: Lawson flips decided exactly, but only strictly inside the circle:
// an exactly cocircular quad keeps the diagonal its insertion made (a
// constrained Delaunay mesh too, the tie broken as a plain Lawson program does).
// FloatInput: the exact mesh of the input with its vertices rounded to the
// nearest float, as a program that reads its input as float and computes in
// double has it (float-input); the constructor throws std::invalid_argument when
// that rounding makes two input vertices one.
enum class MeshReading { Exact, NoFlips, NoFlipsButSplits, DoubleIncircle, FloatPoints, TiesKept, FloatInput };
// "exact", "no-flips", "no-flips-but-splits", "double-incircle", "float-points", "ties-kept", "float-input"
const char* to_string(MeshReading reading);

// The float nearest x, as a double (what a program holding x as float has).
double nearest_float(double x);

// What counts as the paper's choice (docs/AUDIT.md, "Conformance").
struct ReplayRules {
  Method method = Method::Centroid;
  double min_angle_deg = 30;
  // A triangle whose smallest angle is within this many degrees of theta may
  // count as bad or as good. 0: exactly lepp's engines' rule (sin^2 compared
  // with the upper end of the certified bracket of sin^2(theta)).
  double angle_tolerance_deg = 0;
  // A point within this many units of DBL_EPSILON * M of the exact rational
  // choice (per coordinate; M = the largest |coordinate| of the vertices that
  // define the choice) is that choice.
  double point_tolerance_ulps = 8;
  double max_area = 0;  // > 0: a triangle of larger area is bad too (Triangle's -a)
  // The PSLG's regions' area bounds too (RefineOptions::region_area_bounds,
  // Triangle's -a with no number): the engines' rule, ALGORITHM.md section 4.
  bool region_area_bounds = false;
  // When a point is no choice, try the meshes that differ from the replay's
  // by flipping one or two exactly cocircular edges (near the point, or where
  // recent insertions met a tie): the constrained Delaunay insertion is not
  // unique there, and an implementation may have flipped where the replay did not.
  bool follow_cocircular_flips = true;
  // When that fails too, any constrained Delaunay mesh of the same points is
  // tried (any triangulation of each exactly cocircular cell), looking at
  // most at this many triangles per point.
  std::size_t cocircular_search_budget = 200000;
  CentroidReading centroid = CentroidReading::Vertex;
  // A consistent variant of the algorithm (a catalogue rule put in place of
  // the paper's where it applies; Unknown: the paper's own rules). Used to ask
  // whether every step of a trace fits one deviation: AreaCentroid (the area
  // reading), TriangleCentroid, TerminalMidpoint, CentroidNotMidpoint,
  // Remark10Ignored, Remark10Reversed, InexactLength (the paper's rules with
  // near ties of lengths as ties) and InexactThreshold (triangles within double
  // rounding above theta as bad too) have a variant; the others are not a rule
  // set. Replay::allow adds more, part way through a trace.
  Deviation variant = Deviation::Unknown;
  MeshReading mesh = MeshReading::Exact;
};

// One choice the paper allows at this moment.
struct ReplayChoice {
  Tri bad{{-1, -1, -1}};         // a bad triangle whose Lepp ends at the terminal edge (-1s: none found)
  std::vector<Tri> lepp;         // Lepp(bad): bad first, terminal triangle(s) last
  std::array<int, 2> terminal_edge{{-1, -1}};
  Tri t1{{-1, -1, -1}}, t2{{-1, -1, -1}};  // t2 -1s for a constrained terminal edge
  Rule rule = Rule::QuadCentroid;
  Point point;                   // the exact choice, rounded to the nearest doubles
  double distance = 0;           // max(|dx|, |dy|) from the point asked about to the exact choice
  double euclidean = 0;          // the Euclidean distance, for reports
  double tolerance = 0;          // the point tolerance for this choice, same units
  std::array<int, 2> split_edge{{-1, -1}};  // the constrained edge the choice splits, or -1s
  Deviation deviation = Deviation::Unknown;  // a variant's point (ReplayRules::variant); Unknown: the paper's
};

// The catalogue rule a point is, at one step (Replay::diagnose).
struct DeviationMatch {
  Deviation deviation = Deviation::Unknown;
  // Where it matched: the bad (or, for GoodTriangle, good) triangle, its Lepp,
  // the terminal pair, and the rule's point (point, distance, tolerance); rule
  // is the paper's rule at that configuration. Unset (-1s) for Unknown.
  ReplayChoice where;
  std::string what;                  // one line: which point of which configuration
  std::vector<ReplayChoice> paper;   // the paper's choices at that configuration
};

// Theorem 2 on the terminal pair of one replayed step.
struct Theorem2Check {
  bool holds = true;
  int apex = -1;                     // the vertex whose angle is over 120 degrees
  double angle_deg = 0;              // about (display only; the test is exact)
};

class Replay {
 public:
  // pslg must be validated (lepp::validate; std::invalid_argument otherwise); it is copied.
  Replay(const Pslg& pslg, const ReplayRules& rules);
  ~Replay();
  Replay(const Replay&) = delete;
  Replay& operator=(const Replay&) = delete;

  // A choice within tolerance of p that some bad triangle's Lepp (under some
  // resolution of ties) leads to; false if none. Searches around p first (from
  // the terminal triangles near p backwards along the Lepp tree, then one ring of
  // triangles wider, then the cocircular cells' other triangulations), and only
  // then every bad triangle's Lepp (slow; docs/CONFORMANCE.md).
  bool match(const Point& p, ReplayChoice& choice);
  // Inserts p as the reference does: splits choice.split_edge when it is set
  // (and when p lies on a constrained edge), otherwise a Delaunay insertion.
  // Throws std::runtime_error when p cannot be inserted (a vertex already, or
  // outside the domain).
  void insert(const Point& p, const ReplayChoice& choice);
  // From now on match() also takes this variant's points (has_variant), as
  // ReplayRules::variant does from the start: the conformance check continues
  // a trace past a named deviation to name the next.
  void allow(Deviation variant);

  // For reports (slow: walks the Lepp of every bad triangle): every choice of
  // the current mesh, nearest to p first, at most limit; total gets how many.
  std::vector<ReplayChoice> all_choices(const Point& p, std::size_t limit, std::size_t& total);
  // Which catalogue rule p is at the current mesh (slow, for reports: walks
  // the Lepp of every triangle). Call it where match(p) failed.
  DeviationMatch diagnose(const Point& p) const;
  // Theorem 2 (Section 2) on the terminal pair of a choice match() returned,
  // before inserting it: the angles at both apexes of an unconstrained
  // terminal edge are at most 120 degrees, exactly (cos >= -1/2).
  Theorem2Check theorem2(const ReplayChoice& choice) const;
  // The current mesh (domain triangles), canonical.
  Mesh mesh() const;
  std::size_t steiner_points() const;
  // Cocircular ties: the initial CDT's cocircular edges, and the cocircular
  // quads met by the insertions so far (their Delaunay flip is not unique: an
  // implementation may have flipped where the replay did not).
  std::int64_t cocircular_ties() const;
  // Cocircular edges flipped to follow the implementation (follow_cocircular_flips).
  std::int64_t cocircular_flips() const;
  // The last match() gave up its search of the cocircular cells' other
  // triangulations (cocircular_search_budget) before deciding.
  bool cocircular_search_exhausted() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lepp::audit
