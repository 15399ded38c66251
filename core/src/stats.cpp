// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind lepp/stats.h: the statistics `lepp refine` prints and the paper
// plots, computed in double precision for display.
#include "lepp/stats.h"

#include "lepp/angle_args.h"
#include "lepp/refine.h"

#include "angle_args_inline.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace lepp {

double average_lepp_size(const RefineResult& result) {
  return result.lepp_searches ? static_cast<double>(result.lepp_triangles) / static_cast<double>(result.lepp_searches) : 0;
}

namespace {
double len(const Point& a, const Point& b) { return std::hypot(a.x - b.x, a.y - b.y); }
// Twice the area of abc: one expression for every measure, so they see the same double.
double doubled_area(const Point& a, const Point& b, const Point& c) {
  return std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

// mesh_stats skips hypot for a triangle whose squares show it cannot hold a new
// minimum (almost all of them). Squares in [2^-900, 2^900] neither underflow nor
// overflow, so each is within a few 2^-53 of the truth, as hypot is; a triangle is
// skipped only when it clears the minimum by 2^-40, far beyond those roundings.
constexpr double kTiny = 0x1p-900, kHuge = 0x1p900;
constexpr double kClear = 1 + 0x1p-40;
constexpr double kNone = std::numeric_limits<double>::infinity();  // skip nothing
bool safe_square(double v) { return v >= kTiny && v <= kHuge; }

// A triangle whose shortest squared edge is above this has no edge below `shortest`.
double shortest_edge_bound(double shortest) {
  return shortest >= 0x1p-400 && shortest <= 0x1p400 ? shortest * shortest * kClear : kNone;
}
// area_quality is (2 / sqrt 3) area2 / longest^2: a triangle whose area2 / longest
// square is above this has a quality above `min_q`.
double area_quality_bound(double min_q) {
  return min_q >= 0x1p-800 && min_q <= 4 ? min_q * (std::sqrt(3.0) / 2) * kClear : kNone;
}
}  // namespace

double signed_angle_deg(const Point& o, const Point& p, const Point& q) { return signed_degrees(angle_args(o, p, q)); }

double angle_deg(const Point& o, const Point& p, const Point& q) { return std::abs(signed_angle_deg(o, p, q)); }

namespace {
// The shortcut's margins (smallest_angle below).
constexpr double kShorter = 1 - 0x1p-10, kNotThin = 0x1p-20;

// The sides of triangle abc as vectors, dab = b - a, dbc = c - b, dca = a - c
// (scaled_direction's differences), and their squares ab, bc, ca (|a - b|^2 ...: a
// difference's sign does not change its square).
struct Sides {
  Point dab, dbc, dca;
  double ab = 0, bc = 0, ca = 0;
};
inline Sides sides_of(const Point& a, const Point& b, const Point& c) {
  Sides s{{b.x - a.x, b.y - a.y}, {c.x - b.x, c.y - b.y}, {a.x - c.x, a.y - c.y}};
  s.ab = s.dab.x * s.dab.x + s.dab.y * s.dab.y;
  s.bc = s.dbc.x * s.dbc.x + s.dbc.y * s.dbc.y;
  s.ca = s.dca.x * s.dca.x + s.dca.y * s.dca.y;
  return s;
}

// A side's vector as scaled_direction scales it, where the three squares are
// safe_square: each side's larger component m then lies in [2^-451, 2^451) (a smaller
// m would make the square below 2^-900, a larger one above 2^900; rounding is
// monotonic), where scaled_direction takes its power-of-two branch, computed here alone.
inline Point scaled_safe_side(const Point& d) {
  const double scale = detail::power_of_two(-detail::exponent_of(std::max(std::abs(d.x), std::abs(d.y))));
  return {d.x * scale, d.y * scale};
}

// min_angle_deg of triangle abc from its sides (sides_of).
inline double smallest_angle(const Point& a, const Point& b, const Point& c, const Sides& s) {
  // The side clearly shortest (its square below the others' by 2^-10) and the angle
  // opposite it not thin (sine at least about 2^-20): that angle is then smaller than
  // the other two by more than about 2^-31 radians (law of sines), far beyond the ulps
  // of the computed degrees, so it is the minimum of the three bit for bit, from two
  // scaled sides, no comparisons (issue 40: most triangles of a mesh). The sides'
  // vectors are inline what corner_angle_args computes (the same doubles).
  if (safe_square(s.ab) && safe_square(s.bc) && safe_square(s.ca)) {
    const double ab = s.ab, bc = s.bc, ca = s.ca;
    const int k = bc < kShorter * std::min(ab, ca) ? 0 : ca < kShorter * std::min(ab, bc) ? 1 : ab < kShorter * std::min(bc, ca) ? 2 : -1;
    if (k >= 0) {
      // corner_args: corner 0 from ab and -ca, 1 from bc and -ab, 2 from ca and -bc.
      const Point& from = k == 0 ? s.dab : k == 1 ? s.dbc : s.dca;
      const Point& to = k == 0 ? s.dca : k == 1 ? s.dab : s.dbc;
      const AngleArgs at = detail::args_of(scaled_safe_side(from), detail::negated(scaled_safe_side(to)));
      if (std::abs(at.cross) >= kNotThin * (std::abs(at.dot) + std::abs(at.cross))) return std::abs(detail::degrees_of(at));
    }
  }
  const std::array<AngleArgs, 3> at = triangle_angle_args(a, b, c);
  // The angle no other is clearly below, then one atan2 if it is clearly below both
  // others; otherwise (a tie within 2^-40 radians, a degenerate triangle) all three,
  // as the minimum of the three was always taken.
  int k = clearly_smaller(at[1], at[0]) ? 1 : 0;
  if (clearly_smaller(at[2], at[k])) k = 2;
  if (clearly_smaller(at[k], at[(k + 1) % 3]) && clearly_smaller(at[k], at[(k + 2) % 3]))
    return std::abs(signed_degrees(at[k]));
  return std::min({std::abs(signed_degrees(at[0])), std::abs(signed_degrees(at[1])), std::abs(signed_degrees(at[2]))});
}
}  // namespace

double min_angle_deg(const Point& a, const Point& b, const Point& c) { return smallest_angle(a, b, c, sides_of(a, b, c)); }

double max_angle_deg(const Point& a, const Point& b, const Point& c) {
  return std::max({angle_deg(a, b, c), angle_deg(b, c, a), angle_deg(c, a, b)});
}

double radius_ratio(const Point& a, const Point& b, const Point& c) {
  // 2 r / R = 16 area^2 / (|ab| |bc| |ca| (|ab| + |bc| + |ca|)).
  const double area2 = doubled_area(a, b, c);
  const double ab = len(a, b), bc = len(b, c), ca = len(c, a);
  const double den = ab * bc * ca * (ab + bc + ca);
  return den > 0 ? 4.0 * area2 * area2 / den : 0.0;
}

double edge_ratio(const Point& a, const Point& b, const Point& c) {
  const double ab = len(a, b), bc = len(b, c), ca = len(c, a);
  const double lo = std::min({ab, bc, ca});
  return lo > 0 ? std::max({ab, bc, ca}) / lo : std::numeric_limits<double>::infinity();
}

double area_quality(const Point& a, const Point& b, const Point& c) {
  const double area2 = doubled_area(a, b, c);
  double l = std::max({len(a, b), len(b, c), len(c, a)});
  return l > 0 ? (2.0 / std::sqrt(3.0)) * area2 / (l * l) : 0.0;
}

namespace {

// The statistics' running values over some of the triangles: smallest values, which
// MeshStatsJob merges in any order to the same numbers. (The mean's sum would not: the
// job adds the smallest angles in the triangles' order.)
struct StatsPass {
  double min_angle = 180, min_q = std::numeric_limits<double>::infinity();
  double shortest = std::numeric_limits<double>::infinity();
  // Triangles that cannot lower `shortest` or `min_q` are not measured for them.
  double shortest_bound = kNone, quality_bound = kNone;

  // Triangle i's smallest angle, counted into the smallest values.
  double add(const Mesh& mesh, std::size_t i) {
    const Tri& t = mesh.triangles[i];
    const Point &a = mesh.vertices[static_cast<std::size_t>(t[0])], &b = mesh.vertices[static_cast<std::size_t>(t[1])],
                &c = mesh.vertices[static_cast<std::size_t>(t[2])];
    const Sides sides = sides_of(a, b, c);
    const double m = smallest_angle(a, b, c, sides);
    const double ab = sides.ab, bc = sides.bc, ca = sides.ca;
    min_angle = std::min(min_angle, m);
    const bool well_scaled = safe_square(ab) && safe_square(bc) && safe_square(ca);  // false for a NaN too
    const double lo = std::min({ab, bc, ca}), hi = std::max({ab, bc, ca});
    if (!(well_scaled && lo > shortest_bound)) {
      shortest = std::min({shortest, len(a, b), len(b, c), len(c, a)});
      shortest_bound = shortest_edge_bound(shortest);
    }
    const double area2 = doubled_area(a, b, c);
    if (!(well_scaled && area2 >= kTiny && area2 / hi > quality_bound)) {
      min_q = std::min(min_q, area_quality(a, b, c));
      quality_bound = area_quality_bound(min_q);
    }
    return m;
  }
};

}  // namespace

MeshStatsJob::MeshStatsJob(const Mesh& mesh, const Pslg& input, std::size_t chunk)
    : mesh_(mesh), input_(input), chunk_(std::max<std::size_t>(chunk, 1)) {}

void MeshStatsJob::work() {
  StatsPass pass;
  const std::size_t nt = mesh_.triangles.size();
  // No more than the mesh's angles: the fuzzers' meshes of a few triangles each took
  // 128 KiB, zeroed, fresh pages under ASan (57 % of the bytes fuzz_cdt allocated).
  std::vector<double> angles(std::min(chunk_, nt));
  // The triangles come in order of their smallest vertex, so their other two
  // vertices are loads from anywhere in the array: fetched kAhead triangles early.
  constexpr std::size_t kAhead = 8;
  for (;;) {
    const std::size_t chunk = next_chunk_.fetch_add(1, std::memory_order_relaxed);
    const std::size_t begin = chunk * chunk_;
    if (begin >= nt) break;
    const std::size_t end = std::min(nt, begin + chunk_);
    for (std::size_t i = begin; i < end; ++i) {
      if (i + kAhead < nt) {
        const Tri& later = mesh_.triangles[i + kAhead];
        __builtin_prefetch(&mesh_.vertices[static_cast<std::size_t>(later[1])]);
        __builtin_prefetch(&mesh_.vertices[static_cast<std::size_t>(later[2])]);
      }
      angles[i - begin] = pass.add(mesh_, i);
    }
    // The sum in the triangles' order, whichever thread measured them: chunk c's
    // angles are added after chunk c - 1's.
    std::unique_lock<std::mutex> lock(mutex_);
    summed_.wait(lock, [&] { return next_sum_ == chunk; });
    for (std::size_t i = begin; i < end; ++i) sum_ += angles[i - begin];
    ++next_sum_;
    lock.unlock();
    summed_.notify_all();
  }
  std::lock_guard<std::mutex> lock(mutex_);
  min_angle_ = std::min(min_angle_, pass.min_angle);
  min_q_ = std::min(min_q_, pass.min_q);
  shortest_ = std::min(shortest_, pass.shortest);
}

MeshStats MeshStatsJob::result() const {
  MeshStats s;
  s.vertices = mesh_.vertices.size();
  s.triangles = mesh_.triangles.size();
  double input_shortest = std::numeric_limits<double>::infinity();
  for (const Segment& seg : input_.segments)
    input_shortest = std::min(input_shortest, len(input_.vertices[static_cast<std::size_t>(seg.a)],
                                                  input_.vertices[static_cast<std::size_t>(seg.b)]));
  if (!mesh_.triangles.empty()) {
    s.min_angle_deg = min_angle_;
    s.avg_min_angle_deg = sum_ / static_cast<double>(mesh_.triangles.size());
    s.min_area_quality = min_q_;
    s.shortest_edge = shortest_;
    s.shortest_edge_ratio = std::isfinite(input_shortest) && input_shortest > 0 ? shortest_ / input_shortest : 0;
  }
  return s;
}

MeshStats mesh_stats(const Mesh& mesh, const Pslg& input) {
  MeshStatsJob job(mesh, input);
  job.work();
  return job.result();
}

}  // namespace lepp
