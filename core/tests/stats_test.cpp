// SPDX-License-Identifier: GPL-3.0-or-later
// The statistics the CLI, Python and the paper runner print (lepp/stats.h).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <thread>
#include <vector>

#include "lepp/refine.h"
#include "lepp/stats.h"

namespace lepp {
namespace {

TEST(RefineStatistics, AverageLeppSizeIsTrianglesPerSearch) {
  RefineResult r;
  r.lepp_searches = 4;
  r.lepp_triangles = 10;
  EXPECT_DOUBLE_EQ(average_lepp_size(r), 2.5);
  r.lepp_searches = 0;  // nothing refined: 0, not a division by zero
  r.lepp_triangles = 0;
  EXPECT_EQ(average_lepp_size(r), 0.0);
}

std::uint64_t bits(double d) {
  std::uint64_t b;
  std::memcpy(&b, &d, sizeof b);
  return b;
}

// lepp refine's statistics on two threads (MeshStatsJob): the numbers of one, to the
// bit, whichever thread measured which chunk. Tiny chunks on four threads finish out of
// order, so a sum taken in the order chunks finish would differ in its last bits.
// Run under ThreadSanitizer in CI (scripts/ci.d/15-threads-tsan.sh).
TEST(MeshStatistics, ThreadsGiveTheNumbersOfOne) {
  std::mt19937_64 rng(20261207);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  Mesh mesh;
  for (int i = 0; i < 3000; ++i) mesh.vertices.push_back({coordinate(rng), coordinate(rng)});
  while (mesh.triangles.size() < 60000) {  // three distinct corners
    const Tri t{static_cast<int>(rng() % 3000), static_cast<int>(rng() % 3000), static_cast<int>(rng() % 3000)};
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) mesh.triangles.push_back(t);
  }
  Pslg input;
  input.vertices = {{0, 0}, {0.5, 0}};
  input.segments = {{0, 1}};
  const MeshStats one = mesh_stats(mesh, input);
  // Chunks of one triangle, a few, the default, and at the count's boundary: two
  // exact chunks, one exact chunk, one chunk with room to spare.
  for (std::size_t chunk : {std::size_t{1}, std::size_t{7}, std::size_t{16384}, std::size_t{30000}, std::size_t{60000},
                            std::size_t{60001}})
    for (int threads : {1, 2, 4}) {
      MeshStatsJob job(mesh, input, chunk);
      std::vector<std::thread> others;
      for (int t = 1; t < threads; ++t) others.emplace_back([&job] { job.work(); });
      job.work();
      for (std::thread& t : others) t.join();
      const MeshStats s = job.result();
      const std::string where = std::to_string(threads) + " threads, chunks of " + std::to_string(chunk);
      EXPECT_EQ(s.triangles, one.triangles) << where;
      EXPECT_EQ(bits(s.avg_min_angle_deg), bits(one.avg_min_angle_deg)) << where;
      EXPECT_EQ(bits(s.min_angle_deg), bits(one.min_angle_deg)) << where;
      EXPECT_EQ(bits(s.min_area_quality), bits(one.min_area_quality)) << where;
      EXPECT_EQ(bits(s.shortest_edge), bits(one.shortest_edge)) << where;
      EXPECT_EQ(bits(s.shortest_edge_ratio), bits(one.shortest_edge_ratio)) << where;
    }
  // The mean is the sum in the triangles' order: another order gives other bits here
  // (so the comparison above can fail).
  double forward = 0, backward = 0;
  std::vector<double> angles;
  for (const Tri& t : mesh.triangles) {
    Mesh single;
    single.vertices = {mesh.vertices[static_cast<std::size_t>(t[0])], mesh.vertices[static_cast<std::size_t>(t[1])],
                       mesh.vertices[static_cast<std::size_t>(t[2])]};
    single.triangles = {{0, 1, 2}};
    angles.push_back(mesh_stats(single, input).min_angle_deg);
  }
  for (double a : angles) forward += a;
  for (auto a = angles.rbegin(); a != angles.rend(); ++a) backward += *a;
  EXPECT_EQ(bits(forward / 60000), bits(one.avg_min_angle_deg));
  EXPECT_NE(bits(backward / 60000), bits(one.avg_min_angle_deg));
  // No triangle: the job's numbers are mesh_stats's zeros, on two threads too.
  const Mesh empty;
  MeshStatsJob job(empty, input, 7);
  std::thread other([&job] { job.work(); });
  job.work();
  other.join();
  const MeshStats none = job.result(), none_one = mesh_stats(empty, input);
  EXPECT_EQ(none.triangles, 0u);
  EXPECT_EQ(bits(none.avg_min_angle_deg), bits(none_one.avg_min_angle_deg));
  EXPECT_EQ(bits(none.min_angle_deg), bits(none_one.min_angle_deg));
}

}  // namespace
}  // namespace lepp
