// SPDX-License-Identifier: GPL-3.0-or-later
// lepp/angle_args.h and the statistics built on it (issue 31): which of two angles is
// smaller, decided without atan2, at its boundaries (ties, the margin itself), and
// the smallest angle and mesh statistics bit for bit as their definitions give them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "lepp/angle_args.h"
#include "lepp/stats.h"

namespace lepp {
namespace {

// The definitions as they were before issue 31: every angle through atan2, every
// length through hypot. The fast forms must give the same doubles.
Point scaled_by_definition(const Point& o, const Point& p) {
  double dx = p.x - o.x, dy = p.y - o.y;
  if (!std::isfinite(dx) || !std::isfinite(dy)) dx = p.x / 2 - o.x / 2, dy = p.y / 2 - o.y / 2;
  const double m = std::max(std::abs(dx), std::abs(dy));
  if (!(m > 0) || !std::isfinite(m)) return {dx, dy};
  const int e = std::ilogb(m);
  return {std::ldexp(dx, -e), std::ldexp(dy, -e)};
}
double angle_by_definition(const Point& o, const Point& p, const Point& q) {
  const Point u = scaled_by_definition(o, p), v = scaled_by_definition(o, q);
  return std::abs(std::atan2(u.x * v.y - u.y * v.x, u.x * v.x + u.y * v.y) * 180.0 / M_PI);
}
double min_angle_by_definition(const Point& a, const Point& b, const Point& c) {
  return std::min({angle_by_definition(a, b, c), angle_by_definition(b, c, a), angle_by_definition(c, a, b)});
}
double len(const Point& a, const Point& b) { return std::hypot(a.x - b.x, a.y - b.y); }

MeshStats stats_by_definition(const Mesh& mesh) {
  MeshStats s;
  double min_angle = 180, sum = 0, min_q = std::numeric_limits<double>::infinity();
  double shortest = std::numeric_limits<double>::infinity();
  for (const Tri& t : mesh.triangles) {
    const Point &a = mesh.vertices[static_cast<std::size_t>(t[0])], &b = mesh.vertices[static_cast<std::size_t>(t[1])],
                &c = mesh.vertices[static_cast<std::size_t>(t[2])];
    const double m = min_angle_by_definition(a, b, c);
    min_angle = std::min(min_angle, m);
    sum += m;
    const double area2 = std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
    const double l = std::max({len(a, b), len(b, c), len(c, a)});
    min_q = std::min(min_q, l > 0 ? (2.0 / std::sqrt(3.0)) * area2 / (l * l) : 0.0);
    shortest = std::min({shortest, len(a, b), len(b, c), len(c, a)});
  }
  s.min_angle_deg = min_angle;
  s.avg_min_angle_deg = sum / static_cast<double>(mesh.triangles.size());
  s.min_area_quality = min_q;
  s.shortest_edge = shortest;
  return s;
}

// Bit for bit (EXPECT_EQ would call -0 and 0 equal).
::testing::AssertionResult same_bits(double a, double b) {
  if (std::memcmp(&a, &b, sizeof a) == 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << std::hexfloat << a << " and " << b << " differ";
}

// The triangle's three angles: at a, at b, at c.
std::array<AngleArgs, 3> angles(const Point& a, const Point& b, const Point& c) { return triangle_angle_args(a, b, c); }

TEST(ClearlySmaller, ATieIsNeverClearlySmaller) {
  // Equilateral (60, 60, 60 up to the rounding of sqrt 3): no angle clearly below another.
  const auto eq = angles({0, 0}, {1, 0}, {0.5, std::sqrt(3.0) / 2});
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_FALSE(clearly_smaller(eq[static_cast<std::size_t>(i)], eq[static_cast<std::size_t>(j)])) << i << " " << j;
  // Right isosceles: 45 and 45 exactly, neither below the other.
  const auto right = angles({0, 0}, {1, 0}, {0, 1});
  EXPECT_FALSE(clearly_smaller(right[1], right[2]));
  EXPECT_FALSE(clearly_smaller(right[2], right[1]));
  // Mirror-symmetric with base angles near 30 degrees: an exact tie at the threshold.
  const auto at30 = angles({-1, 0}, {1, 0}, {0, std::tan(M_PI / 6)});
  EXPECT_FALSE(clearly_smaller(at30[0], at30[1]));
  EXPECT_FALSE(clearly_smaller(at30[1], at30[0]));
  EXPECT_FALSE(clearly_smaller(at30[0], at30[0]));
}

TEST(ClearlySmaller, OrdersDistinctAngles) {
  const auto right = angles({0, 0}, {1, 0}, {0, 1});  // 90 at the origin, 45 at the others
  EXPECT_TRUE(clearly_smaller(right[1], right[0]));
  EXPECT_TRUE(clearly_smaller(right[2], right[0]));
  EXPECT_FALSE(clearly_smaller(right[0], right[1]));
  // 30, 60, 90 degrees (up to the rounding of sqrt 3): 30 at b, 60 at c, 90 at a.
  const auto t = angles({0, 0}, {std::sqrt(3.0), 0}, {0, 1});
  EXPECT_TRUE(clearly_smaller(t[1], t[2]));
  EXPECT_TRUE(clearly_smaller(t[2], t[0]));
  EXPECT_TRUE(clearly_smaller(t[1], t[0]));
  EXPECT_FALSE(clearly_smaller(t[2], t[1]));
  EXPECT_FALSE(clearly_smaller(t[0], t[2]));
  // Obtuse against acute: 120 and 30 (an angle is read in [0, 180], cross's sign aside).
  const AngleArgs obtuse{-std::sqrt(3.0) / 2, -0.5}, acute{0.5, std::sqrt(3.0) / 2};
  EXPECT_TRUE(clearly_smaller(acute, obtuse));
  EXPECT_FALSE(clearly_smaller(obtuse, acute));
}

TEST(ClearlySmaller, TheMarginIsStrict) {
  // Angle 0 against b = (cross 1, dot 2^40 - 1): y_b x_a - y_a x_b = 1, and the bound
  // (|x_a| + y_a)(|x_b| + y_b) is 2^40, so the difference is exactly 2^-40 times the
  // bound: not clearly smaller (a "greater or equal" would say it is).
  const AngleArgs zero{0, 1};
  EXPECT_FALSE(clearly_smaller(zero, AngleArgs{1, 0x1p40 - 1}));
  // One step wider (bound 2^40 - 1): clearly smaller.
  EXPECT_TRUE(clearly_smaller(zero, AngleArgs{1, 0x1p40 - 2}));
  // Two angles near 30 degrees, 2^-36 radians apart: decided; 2^-44 apart: a tie.
  auto at = [](double radians) { return AngleArgs{std::sin(radians), std::cos(radians)}; };
  const double theta = M_PI / 6;
  EXPECT_TRUE(clearly_smaller(at(theta), at(theta + 0x1p-36)));
  EXPECT_FALSE(clearly_smaller(at(theta + 0x1p-36), at(theta)));
  EXPECT_FALSE(clearly_smaller(at(theta), at(theta + 0x1p-44)));
  EXPECT_FALSE(clearly_smaller(at(theta + 0x1p-44), at(theta)));
}

TEST(ClearlySmaller, NothingNotFiniteOrDegenerateIsClearlySmaller) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const AngleArgs small{0.1, 1};
  EXPECT_FALSE(clearly_smaller(AngleArgs{nan, 1}, AngleArgs{1, 0}));
  EXPECT_FALSE(clearly_smaller(small, AngleArgs{nan, 1}));
  EXPECT_FALSE(clearly_smaller(small, AngleArgs{inf, 1}));
  EXPECT_FALSE(clearly_smaller(AngleArgs{0, 0}, small));  // a side of length 0
}

// Triangles whose smallest angle is at each corner in turn, ties, degenerate ones,
// and the magnitudes of the hostile corpus.
std::vector<std::array<Point, 3>> boundary_triangles() {
  const double s3 = std::sqrt(3.0);
  std::vector<std::array<Point, 3>> base = {
      {Point{0, 0}, Point{1, 0}, Point{0.5, s3 / 2}},        // equilateral
      {Point{0, 0}, Point{1, 0}, Point{0, 1}},               // right isosceles
      {Point{-1, 0}, Point{1, 0}, Point{0, std::tan(M_PI / 6)}},  // 30, 30, 120
      {Point{0, 0}, Point{s3, 0}, Point{0, 1}},              // 30, 60, 90
      {Point{0, 0}, Point{1, 0}, Point{0.5, 1e-9}},          // a needle, two tiny angles
      {Point{0, 0}, Point{1, 0}, Point{2, 0}},               // collinear
      {Point{0, 0}, Point{0, 0}, Point{1, 1}},               // a side of length 0
      {Point{0, 0}, Point{0, 0}, Point{0, 0}},               // all one point
  };
  std::vector<std::array<Point, 3>> all;
  for (const auto& t : base)
    for (double scale : {1.0, 0x1p-600, 0x1p600, 0x1p-1040, 0x1p1020, -3.0})
      for (int r = 0; r < 3; ++r)  // each corner first
        all.push_back({Point{t[r].x * scale, t[r].y * scale}, Point{t[(r + 1) % 3].x * scale, t[(r + 1) % 3].y * scale},
                       Point{t[(r + 2) % 3].x * scale, t[(r + 2) % 3].y * scale}});
  // Far from the origin: coordinates near 1e300 whose differences overflow.
  all.push_back({Point{-1.5e308, 0}, Point{1.5e308, 0}, Point{0, 1e308}});
  return all;
}

// Random triangles and near-isosceles ones (two angles within an ulp or so); around
// min_angle_deg's shortcut (the shortest side's square 2^-10 below the others', the
// angle opposite it of sine 2^-20): two sides in a ratio near that margin, apex angles
// from needles to wide; needles with two tiny angles, their sides in a ratio just past
// the margin (the two angles' rounding, of a cross product of nearly parallel sides, is
// then as large as their difference). n of each kind, every corner first in turn.
std::vector<std::array<Point, 3>> random_and_margin_triangles(int n) {
  std::vector<std::array<Point, 3>> all;
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < n; ++i) {
    const Point a{u(rng), u(rng)};
    Point b{u(rng), u(rng)}, c{u(rng), u(rng)};
    if (i % 2) {
      const double turn = u(rng) * 6.283, apex = 0.1 + u(rng) * 2.9;
      b = {a.x + std::cos(turn), a.y + std::sin(turn)};
      c = {a.x + std::cos(turn + apex), a.y + std::sin(turn + apex)};
    }
    all.push_back({a, b, c});
  }
  auto rotated = [](const std::array<Point, 3>& t, int r) {
    return std::array<Point, 3>{t[static_cast<std::size_t>(r)], t[static_cast<std::size_t>((r + 1) % 3)],
                                t[static_cast<std::size_t>((r + 2) % 3)]};
  };
  for (int i = 0; i < n; ++i) {
    const double apex = std::ldexp(0.5 + u(rng), -static_cast<int>(u(rng) * 40));  // 2^-40 to 1.5 radians
    const double ratio = 1 - std::ldexp(u(rng), -static_cast<int>(4 + u(rng) * 12));  // 1 - 2^-4 to 1 - 2^-16
    const double turn = u(rng) * 6.283;
    const Point o{u(rng), u(rng)};
    const Point p{o.x + std::cos(turn), o.y + std::sin(turn)};
    const Point q{o.x + ratio * std::cos(turn + apex), o.y + ratio * std::sin(turn + apex)};
    all.push_back(rotated({o, p, q}, i % 3));
  }
  for (int i = 0; i < n; ++i) {
    const double off = std::ldexp(0.5 + u(rng), -static_cast<int>(10 + u(rng) * 6));
    const double height = std::ldexp(0.5 + u(rng), -static_cast<int>(10 + u(rng) * 40));
    const double cs = std::cos(u(rng) * 6.283), sn = std::sqrt(1 - cs * cs);  // turned off the axes
    const Point o{u(rng), u(rng)};
    auto turned = [&](double x, double y) { return Point{o.x + cs * x - sn * y, o.y + sn * x + cs * y}; };
    all.push_back(rotated({o, turned(1, 0), turned(0.5 - off, height)}, i % 3));
  }
  return all;
}

TEST(SmallestAngle, IsTheMinimumOfTheThreeAnglesBitForBit) {
  for (const auto& t : boundary_triangles())
    EXPECT_TRUE(same_bits(min_angle_deg(t[0], t[1], t[2]), min_angle_by_definition(t[0], t[1], t[2])))
        << std::hexfloat << t[0].x << "," << t[0].y << " " << t[1].x << "," << t[1].y << " " << t[2].x << "," << t[2].y;
  const std::vector<std::array<Point, 3>> random = random_and_margin_triangles(200000);
  for (std::size_t i = 0; i < random.size(); ++i) {
    const Point &a = random[i][0], &b = random[i][1], &c = random[i][2];
    ASSERT_TRUE(same_bits(min_angle_deg(a, b, c), min_angle_by_definition(a, b, c)))
        << i << std::hexfloat << " " << a.x << "," << a.y << " " << b.x << "," << b.y << " " << c.x << "," << c.y;
  }
}

// mesh_stats takes each triangle's smallest angle from its side vectors inline
// (stats.cpp, issue 40), not through min_angle_deg: each triangle alone as a mesh,
// its smallest and average angle are the definition's, bit for bit, on the same
// triangles, and near the squares' bounds of that path (sides about 2^-450 and 2^450,
// squares about 2^-900 and 2^900).
TEST(MeshStatistics, EachTrianglesSmallestAngleIsItsDefinitionBitForBit) {
  std::vector<std::array<Point, 3>> all = boundary_triangles();
  const std::vector<std::array<Point, 3>> random = random_and_margin_triangles(50000);
  all.insert(all.end(), random.begin(), random.end());
  for (double scale : {0x1p-451, 0x1p-450, 0x1p-449, 0x1p449, 0x1p450, 0x1p451})
    for (std::size_t i = 0; i < random.size(); i += 97) {
      std::array<Point, 3> t = random[i];
      for (Point& p : t) p = {p.x * scale, p.y * scale};
      all.push_back(t);
    }
  const Pslg none;
  Mesh one;
  one.triangles = {{0, 1, 2}};
  for (std::size_t i = 0; i < all.size(); ++i) {
    const Point &a = all[i][0], &b = all[i][1], &c = all[i][2];
    one.vertices = {a, b, c};
    const MeshStats s = mesh_stats(one, none);
    const double expected = min_angle_by_definition(a, b, c);
    ASSERT_TRUE(same_bits(s.min_angle_deg, std::min(180.0, expected)) && same_bits(s.avg_min_angle_deg, expected))
        << i << std::hexfloat << " " << a.x << "," << a.y << " " << b.x << "," << b.y << " " << c.x << "," << c.y << ": "
        << s.min_angle_deg << " " << s.avg_min_angle_deg << " against " << expected;
  }
}

TEST(SmallestAngle, EveryAngleIsItsDefinition) {
  for (const auto& t : boundary_triangles())
    for (int r = 0; r < 3; ++r) {
      const Point &o = t[static_cast<std::size_t>(r)], &p = t[static_cast<std::size_t>((r + 1) % 3)],
                  &q = t[static_cast<std::size_t>((r + 2) % 3)];
      EXPECT_TRUE(same_bits(angle_deg(o, p, q), angle_by_definition(o, p, q)));
      EXPECT_TRUE(same_bits(std::abs(signed_degrees(triangle_angle_args(t[0], t[1], t[2])[static_cast<std::size_t>(r)])),
                            angle_by_definition(o, p, q)));
    }
}

// A jittered grid of n x n squares, two triangles each, scaled; the order of the
// triangles shuffled so that the minima are found anywhere in the loop.
Mesh jittered_grid(int n, double scale, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  Mesh mesh;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) mesh.vertices.push_back({(i + jitter(rng)) * scale, (j + jitter(rng)) * scale});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int v = j * (n + 1) + i;
      mesh.triangles.push_back({v, v + 1, v + n + 2});
      mesh.triangles.push_back({v, v + n + 2, v + n + 1});
    }
  std::shuffle(mesh.triangles.begin(), mesh.triangles.end(), rng);
  return mesh;
}

TEST(MeshStatistics, AreTheirDefinitionsBitForBit) {
  const Pslg none;
  for (double scale : {1.0, 1e-3, 0x1p-500, 0x1p500, 0x1p-530, 0x1p-1000, 0x1p-1060, 0x1p1000})
    for (std::uint64_t seed : {1, 2, 3}) {
      const Mesh mesh = jittered_grid(40, scale, seed);
      const MeshStats fast = mesh_stats(mesh, none), slow = stats_by_definition(mesh);
      EXPECT_TRUE(same_bits(fast.min_angle_deg, slow.min_angle_deg)) << scale;
      EXPECT_TRUE(same_bits(fast.avg_min_angle_deg, slow.avg_min_angle_deg)) << scale;
      EXPECT_TRUE(same_bits(fast.min_area_quality, slow.min_area_quality)) << scale;
      EXPECT_TRUE(same_bits(fast.shortest_edge, slow.shortest_edge)) << scale;
    }
  // Equal triangles everywhere: every one ties the minima (an exact grid of right isosceles).
  Mesh grid = jittered_grid(10, 1, 4);
  for (std::size_t v = 0; v < grid.vertices.size(); ++v) grid.vertices[v] = {double(v % 11), double(v / 11)};
  const MeshStats fast = mesh_stats(grid, none), slow = stats_by_definition(grid);
  EXPECT_TRUE(same_bits(fast.min_area_quality, slow.min_area_quality));
  EXPECT_TRUE(same_bits(fast.shortest_edge, slow.shortest_edge));
  EXPECT_TRUE(same_bits(fast.avg_min_angle_deg, slow.avg_min_angle_deg));
}

}  // namespace
}  // namespace lepp
