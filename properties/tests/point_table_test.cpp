// SPDX-License-Identifier: GPL-3.0-or-later
// The certifier's table of points by value (properties/certify/src/point_table.h),
// against std::map on the same points: tens of thousands of them, in few distinct
// values (long probes past others' slots), with -0 and +0 one point, and NaN equal
// to nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "point_table.h"

namespace lepp::certify {
namespace {

// Points as Point's == compares them: +0.0 for -0.0.
std::pair<double, double> key(const Point& p) { return {p.x + 0.0, p.y + 0.0}; }

TEST(PointTable, EachPointIsFoundAsItsFirstIdAndNoOtherIs) {
  std::mt19937_64 rng(20261207);
  std::uniform_int_distribution<int> small(-40, 40);
  std::vector<Point> points;
  for (int i = 0; i < 30000; ++i) {
    const double x = small(rng) * 0.25, y = small(rng) * 0.25;
    points.push_back({(rng() & 1) ? -x : x, y});  // -0 beside +0 where x is 0
  }
  points.push_back({std::nan(""), 1});
  points.push_back({std::nan(""), 1});
  PointTable table(points.size());
  auto point_of = [&](int i) -> const Point& { return points[static_cast<std::size_t>(i)]; };
  std::map<std::pair<double, double>, int> first;
  for (std::size_t i = 0; i < points.size(); ++i) {
    int& slot = table.slot(points[i], point_of);
    const bool nan = std::isnan(points[i].x);
    const auto [it, fresh] = nan ? std::make_pair(first.end(), true) : first.emplace(key(points[i]), static_cast<int>(i));
    EXPECT_EQ(slot < 0, fresh) << i;
    if (!fresh) EXPECT_EQ(slot, it->second) << i;
    if (slot < 0) slot = static_cast<int>(i);
  }
  ASSERT_GT(first.size(), 5000u);
  for (const auto& [k, id] : first) {
    EXPECT_EQ(table.find({k.first, k.second}, point_of), id);
    if (k.first == 0) EXPECT_EQ(table.find({-0.0, k.second}, point_of), id);
  }
  EXPECT_EQ(table.find({0.125, 0}, point_of), -1) << "no point there";
  EXPECT_EQ(table.find({std::nan(""), 1}, point_of), -1) << "NaN is equal to nothing";
}

}  // namespace
}  // namespace lepp::certify
