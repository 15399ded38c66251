// SPDX-License-Identifier: GPL-3.0-or-later
// The statistics `lepp refine` prints and the paper plots, in double precision
// (for display; decisions about angles are made exactly elsewhere).
#pragma once
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <limits>
#include <mutex>

#include "lepp/mesh.h"
#include "lepp/pslg.h"

namespace lepp {

struct RefineResult;

// The average Lepp size: triangles visited per Lepp search (the paper's Lepp
// statistic; 0 when no search was made). One definition for the CLI, Python and
// the paper runner.
double average_lepp_size(const RefineResult& result);

struct MeshStats {
  std::size_t vertices = 0, triangles = 0;
  double min_angle_deg = 0;        // smallest angle of any triangle
  double avg_min_angle_deg = 0;    // mean over triangles of their smallest angle
  double min_area_quality = 0;     // min q(t) = (4/sqrt 3) area / longest^2, 1 for equilateral
  double shortest_edge = 0;        // shortest mesh edge
  double shortest_edge_ratio = 0;  // shortest mesh edge / shortest input segment
};

MeshStats mesh_stats(const Mesh& mesh, const Pslg& input);

// mesh_stats on more than one thread: each calls work(), which takes chunks of
// triangles in turn until none is left; result() once every work() has returned
// gives mesh_stats's numbers to the bit (the smallest values merge in any order, and
// the smallest angles are summed in the triangles' order, chunk after chunk). lepp
// refine's writing thread joins the statistics' once its files are written.
class MeshStatsJob {
 public:
  // Both must outlive the job. `chunk`: triangles a turn (tests take tiny ones).
  MeshStatsJob(const Mesh& mesh, const Pslg& input, std::size_t chunk = kChunk);
  MeshStatsJob(const MeshStatsJob&) = delete;
  MeshStatsJob& operator=(const MeshStatsJob&) = delete;
  void work();
  MeshStats result() const;

 private:
  static constexpr std::size_t kChunk = std::size_t{1} << 14;  // 128 KiB of angles, kept in cache
  const Mesh& mesh_;
  const Pslg& input_;
  const std::size_t chunk_;
  std::atomic<std::size_t> next_chunk_{0};
  std::mutex mutex_;
  std::condition_variable summed_;
  std::size_t next_sum_ = 0;  // under mutex_: the chunk whose angles are added next
  double sum_ = 0;            // under mutex_
  double min_angle_ = 180, min_q_ = std::numeric_limits<double>::infinity();  // under mutex_
  double shortest_ = std::numeric_limits<double>::infinity();                  // under mutex_
};

// The angle at o between o->p and o->q, degrees in [0, 180], and its signed form
// (counter-clockwise from o->p to o->q, in (-180, 180]). Right at any magnitude:
// each vector is scaled by a power of two before the products, so coordinates
// near 1e300 do not overflow and near 1e-300 do not underflow (issue 19).
double angle_deg(const Point& o, const Point& p, const Point& q);
double signed_angle_deg(const Point& o, const Point& p, const Point& q);

// Smallest angle of triangle abc in degrees (right at any magnitude), and its area quality q.
double min_angle_deg(const Point& a, const Point& b, const Point& c);
double area_quality(const Point& a, const Point& b, const Point& c);
// The other per-triangle measures the .vtu carries (docs/FORMATS.md), each 1
// for an equilateral triangle: largest angle in degrees (60 at best); radius
// ratio 2 r_in / R_circ (in (0, 1], 0 when degenerate); edge ratio longest /
// shortest edge (>= 1, infinite when an edge has length 0).
double max_angle_deg(const Point& a, const Point& b, const Point& c);
double radius_ratio(const Point& a, const Point& b, const Point& c);
double edge_ratio(const Point& a, const Point& b, const Point& c);

}  // namespace lepp
