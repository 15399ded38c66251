// SPDX-License-Identifier: GPL-3.0-or-later
// Writes the structured fuzz seeds: small PSLGs of each kind (polygons, holes,
// point sets, small input angles, clustered boundaries) at several theta and
// both methods, encoded as fuzz_refine, fuzz_differential and fuzz_cdt read them.
//   fuzz_make_seeds OUT_DIR
//   fuzz_make_seeds --bake IN OUT   re-encodes a finding with the environment's
//     LEPP_FUZZ_METHOD / LEPP_FUZZ_THETA applied, so it replays without them
//   fuzz_make_seeds --poly IN OUT.poly   writes the PSLG a structured finding describes
//     (the environment applied) as a Triangle .poly, and prints method and theta, so
//     `lepp refine` and `lepp certify` (any version) can run it
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "lepp/io.h"
#include "support/fuzz_input.h"

using lepp::fuzz::FuzzInput;
using lepp::fuzz::GridPoint;

namespace {

FuzzInput polygon(int grid, std::vector<GridPoint> points, bool closed = true) {
  FuzzInput in;
  in.grid = grid;
  in.vertices = std::move(points);
  const int n = static_cast<int>(in.vertices.size());
  for (int i = 0; i + 1 < n || (closed && i < n); ++i) in.segments.push_back({i, (i + 1) % n});
  return in;
}

void add_loop(FuzzInput& in, std::vector<GridPoint> points) {
  const int first = static_cast<int>(in.vertices.size()), n = static_cast<int>(points.size());
  for (const GridPoint& p : points) in.vertices.push_back(p);
  for (int i = 0; i < n; ++i) in.segments.push_back({first + i, first + (i + 1) % n});
}

std::vector<std::pair<std::string, FuzzInput>> shapes() {
  std::vector<std::pair<std::string, FuzzInput>> s;
  s.emplace_back("triangle", polygon(8, {{0, 0}, {8, 0}, {3, 5}}));
  s.emplace_back("square", polygon(8, {{0, 0}, {8, 0}, {8, 8}, {0, 8}}));
  FuzzInput dense = polygon(16, {{0, 0}, {4, 0}, {8, 0}, {12, 0}, {16, 0}, {16, 16}, {0, 16}});
  s.emplace_back("square-dense-side", dense);
  s.emplace_back("l-shape", polygon(8, {{0, 0}, {8, 0}, {8, 3}, {3, 3}, {3, 8}, {0, 8}}));
  FuzzInput holed = polygon(12, {{0, 0}, {12, 0}, {12, 12}, {0, 12}});
  add_loop(holed, {{4, 4}, {8, 4}, {8, 8}, {4, 8}});
  holed.holes.push_back({12, 12});  // (6, 6) on the half grid
  s.emplace_back("square-with-hole", holed);
  FuzzInput points;
  points.grid = 10;
  points.vertices = {{0, 0}, {10, 1}, {3, 9}, {7, 4}, {2, 5}, {9, 9}, {5, 2}};
  s.emplace_back("point-set", points);
  s.emplace_back("thin-wedge", polygon(20, {{0, 0}, {20, 3}, {20, 6}}));  // about 8 degrees at the apex
  s.emplace_back("needle-corner", polygon(32, {{0, 0}, {32, 0}, {32, 32}, {1, 32}}));
  s.emplace_back("zigzag", polygon(12, {{0, 0}, {12, 0}, {12, 6}, {9, 3}, {6, 6}, {3, 3}, {0, 6}}));
  s.emplace_back("octagon", polygon(12, {{4, 0}, {8, 0}, {12, 4}, {12, 8}, {8, 12}, {4, 12}, {0, 8}, {0, 4}}));
  FuzzInput interior = polygon(16, {{0, 0}, {16, 0}, {16, 8}, {0, 8}});
  interior.vertices.push_back({5, 4});
  interior.vertices.push_back({11, 4});
  interior.segments.push_back({4, 5});  // a free segment inside
  s.emplace_back("rect-inner-segment", interior);
  s.emplace_back("clustered-rect", polygon(40, {{0, 0}, {20, 0}, {30, 0}, {35, 0}, {38, 0}, {40, 0}, {40, 20},
                                                {39, 20}, {36, 20}, {30, 20}, {0, 20}}));
  s.emplace_back("open-chain", polygon(10, {{0, 0}, {5, 2}, {10, 0}, {10, 10}}, false));
  // Issue 20's families, the limit of double precision: vertices a few ulps
  // apart, alone or at a large offset (fuzz_input.h: offset 2^(k - 1)).
  auto ulps = [](int k) { return std::pair<int, int>{k % 2 ? k / 2 + 1 : -(k / 2 + 1), k % 3 - 1}; };
  FuzzInput diagonal;  // the unit square's corners, points on its diagonal, a cluster at its centre
  diagonal.grid = 40;
  diagonal.vertices = {{0, 0}, {40, 0}, {40, 40}, {0, 40}};
  for (int t = 2; t < 40; t += 5) diagonal.vertices.push_back({t, t});
  diagonal.vertices.push_back({20, 20});
  lepp::fuzz::add_cluster(diagonal, static_cast<int>(diagonal.vertices.size()) - 1, 6, ulps);
  s.emplace_back("precision-diagonal-cluster", diagonal);
  FuzzInput far = polygon(8, {{0, 0}, {8, 0}, {8, 8}, {0, 8}});
  far.vertices.push_back({3, 5});
  far.offset = 41;  // coordinates near 2^40: a grid step of 1 keeps 12 bits of fraction
  lepp::fuzz::add_cluster(far, 4, 3, ulps);
  s.emplace_back("precision-offset-square", far);
  FuzzInput dups;  // a point set with near-duplicates of several points
  dups.grid = 16;
  dups.vertices = {{0, 0}, {16, 1}, {5, 15}, {11, 7}, {3, 8}, {14, 14}, {8, 3}};
  for (int v : {1, 3, 5}) lepp::fuzz::add_cluster(dups, v, 2, ulps);
  dups.offset = 21;
  s.emplace_back("precision-near-duplicates", dups);
  FuzzInput edge = polygon(12, {{0, 0}, {6, 0}, {12, 0}, {12, 6}, {0, 6}});
  lepp::fuzz::add_cluster(edge, 1, 3, ulps);  // copies of a boundary vertex, a few ulps off the segment's line
  s.emplace_back("precision-off-segment", edge);
  return s;
}

}  // namespace

int bake(const char* in_path, const char* out_path) {
  std::ifstream in(in_path, std::ios::binary);
  const std::vector<char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  FuzzInput input = lepp::fuzz::decode(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  lepp::fuzz::apply_environment(input);
  const std::vector<std::uint8_t> out = lepp::fuzz::encode(input);
  std::ofstream(out_path, std::ios::binary).write(reinterpret_cast<const char*>(out.data()), static_cast<std::streamsize>(out.size()));
  std::printf("%s\n", lepp::fuzz::describe(input).c_str());
  return 0;
}

int poly(const char* in_path, const char* out_path) {
  std::ifstream in(in_path, std::ios::binary);
  const std::vector<char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  FuzzInput input = lepp::fuzz::decode(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  lepp::fuzz::apply_environment(input);
  lepp::write_poly(out_path, lepp::fuzz::to_pslg(input));
  const lepp::RefineOptions o = lepp::fuzz::options_of(input);
  std::printf("--method %s --min-angle %.17g --order %s\n", lepp::to_string(o.method), o.min_angle_deg, lepp::to_string(o.order));
  return 0;
}

int main(int argc, char** argv) {
  if (argc == 4 && std::string(argv[1]) == "--bake") return bake(argv[2], argv[3]);
  if (argc == 4 && std::string(argv[1]) == "--poly") return poly(argv[2], argv[3]);
  // An option it does not know (--help) is no directory to fill.
  if (argc != 2 || argv[1][0] == '-') {
    std::fprintf(stderr,
                 "usage: fuzz_make_seeds OUT_DIR | --bake IN OUT | --poly FUZZ_INPUT OUT.poly\n");
    return argc == 2 && std::string(argv[1]) == "--help" ? 0 : 2;
  }
  const std::filesystem::path out = argv[1];
  std::filesystem::create_directories(out);
  const struct { int theta_tenths, method; } settings[] = {{200, 0}, {300, 0}, {200, 1}, {250, 1}, {340, 0}};
  int written = 0;
  for (auto [name, shape] : shapes()) {
    for (const auto& setting : settings) {
      shape.theta_tenths = setting.theta_tenths;
      shape.method = setting.method;
      const std::vector<std::uint8_t> bytes = lepp::fuzz::encode(shape);
      const std::string file = name + "-" + lepp::to_string(setting.method ? lepp::Method::Midpoint : lepp::Method::Centroid) + "-" +
                               std::to_string(setting.theta_tenths / 10) + ".bin";
      std::ofstream(out / file, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                                       static_cast<std::streamsize>(bytes.size()));
      ++written;
    }
  }
  std::printf("wrote %d seeds to %s\n", written, out.c_str());
  return 0;
}
