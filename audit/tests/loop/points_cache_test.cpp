// SPDX-License-Identifier: GPL-3.0-or-later
// The comparison points cache's key (issue 30, item 7): an entry is found again
// for the same engine, input, theta and method, and for no change of any one of
// them, down to one ulp of a coordinate, a hole included. Kills
// audit-cache-key-without-holes, audit-cache-key-without-theta,
// audit-cache-key-without-method and audit-cache-key-without-segments.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lepp/audit/inputs/points_cache.h"

namespace fs = std::filesystem;
using namespace lepp;
using namespace lepp::audit;

namespace {

// A square with a square hole and a region: every part of a PSLG the key covers.
Pslg framed_square() {
  Pslg p;
  p.vertices = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {3, 1}, {3, 3}, {1, 3}};
  for (int i = 0; i < 4; ++i) {
    p.segments.push_back({i, (i + 1) % 4, 1});
    p.segments.push_back({4 + i, 4 + (i + 1) % 4, 2});
  }
  p.holes = {{2, 2}};
  p.regions = {{{0.5, 0.5}, 7, 0.25}};
  return p;
}

TEST(PointsCache, KeyCoversEveryPartOfTheInputThetaAndMethod) {
  const fs::path dir = fs::temp_directory_path() / ("lepp-points-cache-test-" + std::to_string(getpid()));
  fs::remove_all(dir);
  const PointsCache cache(dir.string());
  const std::string engine = "lepp-reference 0.2.0 abc1234";
  const Pslg input = framed_square();
  const double theta = 25;
  cache.put(engine, input, theta, Method::Centroid, {true, 42, 3});

  const auto hit = cache.get(engine, input, theta, Method::Centroid);
  ASSERT_TRUE(hit);
  EXPECT_TRUE(hit->finished);
  EXPECT_EQ(hit->points_added, 42);
  EXPECT_EQ(hit->timeout_seconds, 3);

  auto up = [](double x) { return std::nextafter(x, INFINITY); };
  const std::vector<std::pair<std::string, std::function<void(Pslg&)>>> changes = {
      {"a vertex one ulp over", [&](Pslg& p) { p.vertices[5].x = up(p.vertices[5].x); }},
      {"a segment's end", [](Pslg& p) { p.segments[3].b = 7; }},
      {"a segment fewer", [](Pslg& p) { p.segments.pop_back(); }},
      {"the hole one ulp over", [&](Pslg& p) { p.holes[0].y = up(p.holes[0].y); }},
      {"no hole", [](Pslg& p) { p.holes.clear(); }},
      {"a second hole", [](Pslg& p) { p.holes.push_back({2.5, 2.5}); }},
      {"the region's area bound", [](Pslg& p) { p.regions[0].max_area = 0.5; }},
      {"the region's attribute", [](Pslg& p) { p.regions[0].attribute = 8; }},
  };
  for (const auto& [what, change] : changes) {
    Pslg other = input;
    change(other);
    EXPECT_FALSE(cache.get(engine, other, theta, Method::Centroid)) << what;
  }
  EXPECT_FALSE(cache.get(engine, input, std::nextafter(theta, 0.0), Method::Centroid)) << "theta one ulp under";
  EXPECT_FALSE(cache.get(engine, input, theta, Method::Midpoint)) << "the other method";
  EXPECT_FALSE(cache.get(engine + "x", input, theta, Method::Centroid)) << "another engine";
  fs::remove_all(dir);
}

}  // namespace
