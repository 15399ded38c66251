// SPDX-License-Identifier: GPL-3.0-or-later
// A segment's chain of mesh edges found by walking from one endpoint to the other (segment_walk.h).
#include "segment_walk.h"

#include <algorithm>
#include <unordered_set>

#include "chain_predicates.h"

namespace lepp::certify {
namespace {

// The listed path from a to b, if exactly one: a listed edge from a, then at each
// Steiner point its other listed edge (it has exactly two), every vertex strictly
// ahead of the one before along AB, strictly before B and within 2^-20 |AB| of the
// line or within the walk's loosest tolerance ((k+1) ulp: far from the origin one
// ulp can be many times 2^-20 |AB|), up to an input vertex, which must be b. Empty when no listed path or more
// than one leads from a to b. Where two segments leave a at a small angle and the
// mesh is refined down to ulps of a, the first vertex of the other segment's chain
// can be within one ulp of this segment's line and the straightest step; a walk that
// took it followed the other chain until it left the line by 2^-20 |AB| and then
// stepped across to this chain by an unlisted edge (docs/CERTIFIER.md section 3).
// Which input vertex a listed path ends at tells the two chains apart exactly.
std::vector<int> listed_path(const MeshIndex& ix, int a, int b) {
  if (ix.listed.empty()) return {};
  const Point &A = ix.P(a), &B = ix.P(b);
  const double loose = segment_tolerance(A, B, ix.mesh.vertices.size());
  const auto listed = [&](int v, int w) { return ix.listed.count(edge_key(v, w)) != 0; };
  std::vector<int> found;
  int paths = 0;
  for (const int first : ix.neighbors(a)) {
    if (!listed(a, first)) continue;
    std::vector<int> path{a};
    for (int prev = a, v = first;;) {
      if (v == b) {
        path.push_back(b);
        break;
      }
      if (ix.mesh_to_input[static_cast<std::size_t>(v)] >= 0 || ahead(A, B, ix.P(prev), ix.P(v)) <= 0 || ahead(A, B, ix.P(v), B) <= 0 ||
          !(near_line(A, B, ix.P(v)) || within(A, B, ix.P(v), loose))) {
        path.clear();
        break;
      }
      path.push_back(v);
      int next = -1, listed_edges = 0;
      for (const int w : ix.neighbors(v)) {
        if (!listed(v, w)) continue;
        ++listed_edges;
        if (w != prev) next = w;
      }
      if (listed_edges != 2) {
        path.clear();
        break;
      }
      prev = v, v = next;
    }
    if (!path.empty()) ++paths, found = std::move(path);
  }
  if (paths != 1) found.clear();
  return found;
}

}  // namespace

// Walks from a to b: the listed path, when exactly one leads from a to b; else at
// each vertex the next vertex strictly ahead along AB and strictly before B, and no input vertex, tried in this order: the vertices
// joined by a listed constrained edge within 1, 2, 4, ... ulp up to the loosest
// tolerance, the straightest step first in each tier; then those joined by a
// listed edge within 2^-20 |AB| of the line,
// nearest first; then any within 1, 2, 4, ... ulp up to the loosest tolerance,
// nearest first. Far from the origin the loosest tolerance ((k+1) ulp with k the
// number of mesh vertices) reaches mesh vertices that are not on the segment.
// Depth first: a step that leads nowhere is taken back and the next one tried
// (where two nearly parallel segments leave one vertex, the straightest step may
// be the other segment's, which ends past B: the notch family). A vertex from which
// B was not reached is not tried again (what lies ahead of it does not depend on
// the way there), so the walk visits each vertex once.
// {-1, v} when there is no chain, v where the first choices stopped.
std::vector<int> walk(const MeshIndex& ix, int a, int b) {
  if (std::vector<int> path = listed_path(ix, a, b); !path.empty()) return path;
  const Point &A = ix.P(a), &B = ix.P(b);
  const double loose = segment_tolerance(A, B, ix.mesh.vertices.size());
  std::vector<double> tiers;  // 1, 2, 4, ... ulp, then the loosest
  for (std::size_t k = 0; k < ix.mesh.vertices.size(); k = 2 * k + 1) tiers.push_back(segment_tolerance(A, B, k));
  tiers.push_back(loose);
  // The steps from v, in the order they are tried.
  auto steps = [&](int v) {
    std::vector<int> ahead_of_v;
    for (const int w : ix.neighbors(v)) {
      // Never an input vertex: validate() split every segment at the input vertices
      // exactly on it, so one inside a segment is off it, however near.
      if (ix.mesh_to_input[static_cast<std::size_t>(w)] < 0 && ahead(A, B, ix.P(v), ix.P(w)) > 0 && ahead(A, B, ix.P(w), B) > 0)
        ahead_of_v.push_back(w);
    }
    const auto listed = [&](int w) { return ix.listed.count(edge_key(v, w)) != 0; };
    const auto nearer = [&](int q, int r) { return ahead(A, B, ix.P(q), ix.P(r)) > 0; };
    // Far below the tolerance's scale (features of 1e-300 at a corner of a unit
    // square) a tier holds the first vertices of every segment that leaves v, and
    // the nearest ahead may be another segment's (the precision campaign,
    // docs/FUZZING.md): in the listed tiers the straightest step comes first.
    const auto straighter = [&](int q, int r) {
      const int turn = compare_turn(A, B, ix.P(v), ix.P(q), ix.P(r));
      return turn < 0 || (turn == 0 && nearer(q, r));
    };
    std::vector<int> order;
    auto take = [&](auto&& qualifies, auto&& before) {
      std::vector<int> pool;
      for (int w : ahead_of_v)
        if (qualifies(w) && std::find(order.begin(), order.end(), w) == order.end()) pool.push_back(w);
      std::sort(pool.begin(), pool.end(), before);
      order.insert(order.end(), pool.begin(), pool.end());
    };
    for (double tol : tiers) take([&](int w) { return listed(w) && within(A, B, ix.P(w), tol); }, straighter);
    take([&](int w) { return listed(w) && near_line(A, B, ix.P(w)); }, nearer);
    for (double tol : tiers) take([&](int w) { return within(A, B, ix.P(w), tol); }, nearer);
    return order;
  };
  std::vector<int> chain{a};
  std::vector<std::vector<int>> options{steps(a)};
  std::vector<std::size_t> tried{0};
  std::unordered_set<int> dead;
  int stuck = -1;
  // B ends the chain at once when a listed edge joins it, or any edge where no
  // listed step leads on; else after the listed steps: a split whose rounded
  // point lies off its line may keep the triangle beside its sliver (ALGORITHM.md
  // section 6), so the last chain vertex before B is joined to B by an unlisted
  // edge too, the sliver's base, and the chain goes round through the point.
  const auto listed_step = [&](int v, const std::vector<int>& next) {
    return std::any_of(next.begin(), next.end(), [&](int w) { return ix.listed.count(edge_key(v, w)) != 0; });
  };
  while (!chain.empty()) {
    const int v = chain.back();
    const bool joined = ix.adjacent(v, b);
    if (joined && (ix.listed.count(edge_key(v, b)) != 0 || !listed_step(v, options.back()) ||
                   tried.back() == options.back().size())) {
      chain.push_back(b);
      return chain;
    }
    if (tried.back() == options.back().size()) {  // nothing ahead of here reaches B
      if (stuck < 0) stuck = chain.back();
      dead.insert(chain.back());
      chain.pop_back(), options.pop_back(), tried.pop_back();
      continue;
    }
    const int w = options.back()[tried.back()++];
    if (dead.count(w)) continue;
    chain.push_back(w);
    options.push_back(steps(w));
    tried.push_back(0);
  }
  return {-1, stuck};
}

// Where validate() split a file's segment (at a vertex on it, or with
// --split-crossings at a crossing rounded to doubles), the pieces must stay
// on that segment: each joint within the chain tolerance of the line through
// the segment's ends (segment_tolerance with the joints as interior

}  // namespace lepp::certify
