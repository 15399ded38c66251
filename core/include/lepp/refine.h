// SPDX-License-Identifier: GPL-3.0-or-later
// What both engines take and give: options, outcome, trace, result.
// The decisions behind each field are in docs/ALGORITHM.md.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "lepp/mesh.h"
#include "lepp/pslg.h"
#include "lepp/rounding.h"  // below_precision_floor, kTieSearchStates

namespace lepp {

enum class Method { Centroid, Midpoint };

// The order in which bad triangles are processed (ALGORITHM.md section 7, "Processing order"):
// fifo (default) and lifo push each insertion's new bad triangles in key order at the back or
// the front; flip at the back in the order the insertion and its flips created them; random at
// the back shuffled by a generator seeded with RefineOptions::order_seed (the initial queue too);
// smallest-angle is a priority queue, the smallest angle first; batch runs the queue in rounds of
// triangles whose regions (Lepp, terminal pair, the insertion's cavity and its ring) are apart, so a
// round's insertions are independent of one another.
enum class QueueOrder { Fifo, Lifo, Flip, Random, SmallestAngle, Batch };

// The batch order's looks (ALGORITHM.md section 7, "batch", step 0): a round that
// has looked at kBatchFreeLooks entries plus kBatchLooksPerMember per member ends,
// the rest of its queue waiting as it is. Where most entries wait (a fan that every
// cavity holds) rounds stay short instead of looking at every waiting entry again.
constexpr std::size_t kBatchLooksPerMember = 2;
constexpr std::size_t kBatchFreeLooks = 8;
// The looks a round with `members` members may make (step 0), in both engines.
constexpr std::size_t batch_looks_allowed(int members) {
  return kBatchLooksPerMember * static_cast<std::size_t>(members) + kBatchFreeLooks;
}

enum class Outcome {
  Converged,      // every triangle has smallest angle >= theta (and area <= its size bound)
  Unimprovable,   // converged except for triangles listed as unimprovable (small input angles)
  SteinerBudget,  // stopped: the Steiner budget was used up
  EdgeFloor,      // stopped: an insertion made an edge shorter than the floor
  TimeLimit,      // stopped: the wall-clock limit passed
};

// Which branch of the paper's Select Point / New Select Point chose the point.
enum class Rule {
  TerminalConstrainedMidpoint,   // both methods: terminal edge constrained (or boundary): its midpoint
  TerminalMidpoint,              // midpoint method: midpoint of the unconstrained terminal edge
  SecondLongestMidpoint,         // midpoint: constrained-edge point insertion; centroid: Remark 10 fallback
  QuadCentroid,                  // centroid: neither second-longest edge constrained
  CentroidInOther,               // centroid: one second-longest edge constrained, centroid strictly inside the other triangle
  BothSecondLongestMidpoint,     // centroid: both second-longest edges constrained: midpoint of t1's
};

struct RefineOptions {
  double min_angle_deg = 30;
  Method method = Method::Centroid;
  double max_area = 0;               // 0: no size bound (Triangle's -a)
  // Also the area bounds of the PSLG's regions (Triangle's -a with no number):
  // a triangle larger than the bound of the region it lies in is bad too
  // (with max_area as well, the smaller bound applies). ALGORITHM.md section 4.
  bool region_area_bounds = false;
  QueueOrder order = QueueOrder::Fifo;
  std::uint64_t order_seed = 0;      // the random order's seed (ALGORITHM.md section 7); other orders ignore it
  // Threads for the batch order's selection (the fast engine; ALGORITHM.md section 7):
  // 0 the machine's cores. The mesh is the same for every number; the other orders
  // and the reference engine run on one.
  int threads = 0;
  // Queue entries per thread in a window of the batch order's threads (0: 2048); a
  // window with fewer than a quarter of that per thread runs on one. Only the time
  // depends on it: tests and fuzzers use tiny windows to split small inputs.
  int batch_window = 0;
  std::int64_t max_steiner = -1;     // -1: default_steiner_budget()
  double edge_floor = -1;            // -1: default_edge_floor()
  double time_limit_seconds = 0;     // 0: no limit
  // The bound of the search of every resolution of exact length ties before the
  // precision stop leaves a triangle (ALGORITHM.md section 8b): Lepp states per
  // triangle; 0: no bound (each state is still visited once, so the search ends).
  std::size_t tie_search_states = kTieSearchStates;
  bool trace = false;                // record a TraceStep per insertion
  // Called after every insertion with the current mesh (domain triangles only).
  // Slow: meant for tests on small inputs (Theorem 2 on every intermediate mesh).
  std::function<void(const Mesh&)> on_insertion;
  // Called now and then on long runs with the number of Steiner points so far.
  std::function<void(std::int64_t)> on_progress;
  // The fast engine: called now and then during the refinement, and once before
  // its mesh is made, with the vertices so far (valid during the call only: the
  // array moves as it grows) and how many of them are the input's. The engine only
  // appends vertices, in the output's numbering, so a writer can format the new
  // ones beside the refinement (lepp/node_text_stream.h).
  std::function<void(const std::vector<Point>& vertices, std::size_t input_vertices)> on_vertices;
};

struct TraceStep {
  Tri bad{};                    // the bad triangle being processed
  std::vector<Tri> lepp;        // Lepp(bad): bad first, terminal triangle(s) last
  std::array<int, 2> terminal_edge{};
  Tri t1{};                     // terminal triangle reached by the Lepp
  Tri t2{{-1, -1, -1}};         // its neighbour across the terminal edge, or -1s
  Rule rule = Rule::QuadCentroid;
  Point point;                  // the point inserted
  int split_segment = -1;       // input segment split by the point, or -1
  std::int64_t round = 0;       // the batch order: the round it was inserted in (1, 2, ...); 0 for the other orders
};

// Why a bad triangle was left (ALGORITHM.md sections 8 and 8b).
enum class LeftReason {
  SmallInputAngle,  // its shortest edge spans the wedge of an input angle below theta
  DoublePrecision,  // the point chosen for it, rounded to doubles, cannot be inserted
};

// A bad triangle left as it is: by the small-input-angle rule (apex, segments,
// input angle) or by the precision stop (rule, point; apex and segments -1).
struct UnimprovableTriangle {
  Tri triangle{};
  int apex = -1;                // the input vertex where the two segments meet
  int segment1 = -1, segment2 = -1;
  double input_angle_deg = 0;   // the angle between them at apex (for reports only)
  LeftReason reason = LeftReason::SmallInputAngle;
  Rule rule = Rule::QuadCentroid;  // DoublePrecision: the branch that chose the point
  Point point;                     // DoublePrecision: the chosen point as rounded
  // DoublePrecision: the search of the other tie resolutions stopped at
  // RefineOptions::tie_search_states before it saw every Lepp state (ALGORITHM.md
  // section 8b). Only such a triangle may have an insertable choice the search did not
  // reach (docs/THEOREMS.md, "Where the claim fails").
  bool search_cut = false;
};

struct RefineResult {
  Mesh mesh;
  Outcome outcome = Outcome::Converged;
  std::int64_t steiner_points = 0;
  std::vector<UnimprovableTriangle> unimprovable;
  std::vector<TraceStep> trace;
  std::int64_t cocircular_ties = 0;     // Delaunay decisions that met four cocircular points
  std::int64_t lepp_searches = 0;       // Lepp searches made
  std::int64_t lepp_triangles = 0;      // triangles visited by them (average Lepp size = ratio)
  std::int64_t area_refined = 0;        // bad triangles refined that were too big (skinny or not)
  std::int64_t precision_stops = 0;     // times a chosen point could not be inserted (section 8b)
  std::int64_t tie_resolutions = 0;     // insertions through another resolution of exact length ties (section 8b)
  std::int64_t rounds = 0;              // the batch order: rounds run (section 7); 0 for the other orders
  std::int64_t looks = 0;               // the batch order: entries its rounds looked at (Lepp searched)
  std::string stuck;                    // for a guard outcome: which triangle, its Lepp
  double seconds = 0;
  double cdt_seconds = 0;               // of `seconds`: the initial CDT (and its regions), before refining
};

// What a thread count of 0 means: the machine's cores (at least 1); any other count as it is.
int threads_or_cores(int threads);

// Defaults of the loop guards, a function of the input (ALGORITHM.md, "Termination").
std::int64_t default_steiner_budget(const Pslg& pslg, const RefineOptions& options);
double default_edge_floor(const Pslg& pslg);

const char* to_string(Outcome outcome);
const char* to_string(Rule rule);
const char* to_string(Method method);
const char* to_string(QueueOrder order);
// Both methods, centroid first, and the one named (centroid, midpoint); false for an unknown name.
const std::vector<Method>& all_methods();
bool parse_method(const std::string& name, Method& method);
// Every order, the default first, and the one named (fifo, lifo, flip, random, smallest-angle);
// false for an unknown name.
const std::vector<QueueOrder>& all_queue_orders();
bool parse_queue_order(const std::string& name, QueueOrder& order);
const char* to_string(LeftReason reason);
// 0 converged, 3 any other outcome (the mesh is still written).
int exit_status(Outcome outcome);

}  // namespace lepp
