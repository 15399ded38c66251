// SPDX-License-Identifier: GPL-3.0-or-later
// The structured input of fuzz_refine, fuzz_differential and fuzz_cdt: a PSLG
// on a small integer grid (scaled to doubles), a threshold angle, a method, an
// engine and a queue order. Bytes decode through FuzzedDataProvider, so every
// byte string is some input; encode() writes the bytes decode() reads back, so
// the custom mutator can edit the PSLG and serialize it again.
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "lepp/pslg.h"
#include "lepp/refine.h"

namespace lepp::fuzz {

struct GridPoint {
  int x = 0, y = 0;
};
struct GridSegment {
  int a = 0, b = 0;
};
// Vertex `vertex` moved by dx, dy ulps after scaling and offset (issue 20: points
// a few ulps apart, the limit of double precision).
struct UlpJitter {
  int vertex = 0, dx = 0, dy = 0;
};

struct FuzzInput {
  int method = 0;        // 0 centroid, 1 midpoint
  int engine = 0;        // 0 fast, 1 reference (fuzz_refine only)
  int order = 0;         // 0 fifo, 1 lifo
  int theta_tenths = 200;  // threshold angle in tenths of a degree, 100..360
  int grid = 8;          // coordinates in 0..grid
  int scale = 0;         // index into scales(): the grid step
  std::vector<GridPoint> vertices;
  std::vector<GridSegment> segments;  // may be invalid (crossing, repeated): to_pslg() filters
  std::vector<GridPoint> holes;       // on the half grid: x/2, y/2
  // Read after the holes and a marker byte (kPrecisionMarker), so inputs written
  // before they existed decode unchanged: 0 no offset, k an offset of 2^(k - 1)
  // added to both coordinates; then ulp moves of some vertices.
  int offset = 0;
  std::vector<UlpJitter> jitters;

  static constexpr int kMaxGrid = 40;
  static constexpr int kMaxVertices = 24;
  static constexpr int kMaxSegments = 48;
  static constexpr int kMaxHoles = 3;
  static constexpr int kPrecisionMarker = 0xA5;
  static constexpr int kMaxOffset = 41;
  static constexpr int kMaxJitters = 12;
  static constexpr int kMaxUlps = 4;
};

// The grid steps a fuzz input may use: powers of two keep grid geometry exact
// in double; 0.1 and 1e-3 add rounding.
const std::vector<double>& scales();

FuzzInput decode(const std::uint8_t* data, std::size_t size);
std::vector<std::uint8_t> encode(const FuzzInput& input);

// Applies the environment's overrides, so a run can be pinned to one method
// and one theta band: LEPP_FUZZ_METHOD=centroid|midpoint,
// LEPP_FUZZ_THETA=lo:hi (degrees; the input's theta is mapped into the band),
// and to the limit of double precision: LEPP_FUZZ_PRECISION=1 gives an input
// with neither an offset nor ulp moves a cluster (add_cluster, its vertex and
// moves drawn from the input's own fields, so the mapping is deterministic).
void apply_environment(FuzzInput& input);

// LEPP_FUZZ_PRECISION=1: the campaign on issue 20's families (clusters of
// vertices a few ulps apart, large offsets); the mutator favours those edits.
bool precision_campaign();
bool in_precision_family(const FuzzInput& input);

// Copies of vertex `vertex`, the k-th moved by ulps(k) = (dx, dy) ulps (each
// clamped to kMaxUlps), while there is room for vertices and moves.
void add_cluster(FuzzInput& input, int vertex, int copies, const std::function<std::pair<int, int>(int)>& ulps);

// The PSLG the input describes, with only the segments that keep it a valid
// PSLG (no zero-length, repeated or crossing segments, no vertex inside a
// segment; decided exactly on the grid), then lepp::validate. Throws
// lepp::InputError when no valid PSLG remains (collinear points, ...).
Pslg to_pslg(const FuzzInput& input);
// to_pslg, or nothing when no valid PSLG remains: an input every target skips
// (an invalid input is no finding).
std::optional<Pslg> valid_pslg(const FuzzInput& input);

// The input's method, theta and order (fifo or lifo); LEPP_FUZZ_ORDER (a name of
// `lepp refine --order`, e.g. batch) replaces the order. It is not baked into a
// kept input: replay a finding made under it with the same variable.
RefineOptions options_of(const FuzzInput& input);
double theta_deg(const FuzzInput& input);

// One structural edit: move, add or remove a vertex, add or remove a segment,
// add a hole, change theta, method, order, grid or scale, or make a cluster:
// copies of a vertex a few ulps apart, at a large offset now and then.
void mutate(FuzzInput& input, std::mt19937& rng);

// A one-line description for finding messages.
std::string describe(const FuzzInput& input);

}  // namespace lepp::fuzz
