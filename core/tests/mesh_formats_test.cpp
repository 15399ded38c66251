// SPDX-License-Identifier: GPL-3.0-or-later
// The labels the VTU and Gmsh writers take (markers and regions), and the
// writers' contracts that need no outside reader: format names, errors, and
// the .vtu's appended-data offsets; what lepp refine and Mesh.write choose and
// write (lepp/mesh_output.h). The files themselves are read back by meshio and
// Gmsh in tests/formats/mesh_formats.py.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <system_error>

#include "lepp/mesh_formats.h"
#include "lepp/mesh_labels.h"
#include "lepp/mesh_output.h"
#include "lepp/stats.h"

namespace lepp {
namespace {

// Two unit squares side by side, [0,1]x[0,1] and [1,2]x[0,1], each cut along a
// diagonal; the edge x = 1 between them is constrained (input segment 0, marker
// 7), and so is the bottom edge (input segment 1, marker 0). Vertex 6, the
// middle of the top of the right square, is a Steiner point.
Mesh two_squares() {
  Mesh m;
  m.vertices = {{0, 0}, {1, 0}, {2, 0}, {0, 1}, {1, 1}, {2, 1}, {1.5, 1}};
  m.input_vertices = 6;
  m.triangles = {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 6}, {1, 6, 4}};
  m.constrained_edges = {{1, 4, 0}, {0, 1, 1}};
  return m;
}

Pslg two_squares_input() {
  Pslg p;
  p.segments = {{1, 4, 7}, {0, 1, 0}};
  return p;
}

TEST(MeshLabels, MarkersComeFromTheSegmentOfEachEdge) {
  Mesh m = two_squares();
  m.constrained_edges.push_back({2, 5, -1});  // unknown segment: marker 0
  EXPECT_EQ(mesh_labels(m, two_squares_input()).edge_markers, (std::vector<int>{7, 0, 0}));
}

TEST(MeshLabels, RegionsFloodAcrossUnconstrainedEdgesOnly) {
  const Mesh m = two_squares();
  EXPECT_EQ(triangle_regions(m, {{{0.2, 0.5}, 1, -1}}), (std::vector<int>{1, 1, 0, 0, 0}));
  EXPECT_EQ(triangle_regions(m, {{{1.9, 0.5}, 1, -1}}), (std::vector<int>{0, 0, 1, 1, 1}));
}

TEST(MeshLabels, LaterRegionsOverwriteEarlierOnes) {
  EXPECT_EQ(triangle_regions(two_squares(), {{{0.2, 0.5}, 1, -1}, {{1.9, 0.5}, 2, -1}, {{0.5, 0.9}, 3, -1}}),
            (std::vector<int>{3, 3, 2, 2, 2}));
}

TEST(MeshLabels, PointOnAnUnconstrainedEdgeFloodsOnASegmentOrInputVertexDoesNot) {
  const Mesh m = two_squares();
  EXPECT_EQ(triangle_regions(m, {{{0.5, 0.5}, 1, -1}}), (std::vector<int>{1, 1, 0, 0, 0}));  // on the diagonal
  EXPECT_EQ(triangle_regions(m, {{{1, 0.5}, 1, -1}}), (std::vector<int>(5, 0)));             // on the segment
  EXPECT_EQ(triangle_regions(m, {{{0, 1}, 1, -1}}), (std::vector<int>(5, 0)));               // on an input vertex
  EXPECT_EQ(triangle_regions(m, {{{3, 0.5}, 1, -1}}), (std::vector<int>(5, 0)));             // outside
  // On a Steiner point off every segment: inside a face of the input's CDT, so it floods.
  EXPECT_EQ(triangle_regions(m, {{{1.5, 1}, 1, -1}}), (std::vector<int>{0, 0, 1, 1, 1}));
}

TEST(MeshFormats, NamesRoundTrip) {
  for (MeshFormat f : {MeshFormat::Triangle, MeshFormat::Vtu, MeshFormat::Msh2, MeshFormat::Msh4})
    EXPECT_EQ(parse_mesh_format(to_string(f)), f);
  EXPECT_FALSE(parse_mesh_format("msh3").has_value());
  EXPECT_STREQ(file_extension(MeshFormat::Msh4), ".msh");
}

TEST(MeshOutput, FormatsOnceInTheOrderFirstNamed) {
  const MeshFormatChoice c = choose_mesh_formats({"vtu", "triangle", "vtu", "msh4"});
  EXPECT_EQ(c.formats, (std::vector<MeshFormat>{MeshFormat::Vtu, MeshFormat::Triangle, MeshFormat::Msh4}));
  EXPECT_FALSE(c.unknown);
  EXPECT_FALSE(c.same_file);
  EXPECT_TRUE(choose_mesh_formats({}).formats.empty());
}

TEST(MeshOutput, UnknownNameAndBothMshVersionsAreRefused) {
  const MeshFormatChoice unknown = choose_mesh_formats({"vtu", "stl", "msh3"});
  EXPECT_EQ(unknown.unknown, "stl");  // the first unknown name
  EXPECT_TRUE(unknown.formats.empty());
  EXPECT_EQ(choose_mesh_formats({""}).unknown, "");  // an empty name is no format either
  EXPECT_TRUE(choose_mesh_formats({"msh2", "vtu", "msh4"}).same_file);
  EXPECT_FALSE(choose_mesh_formats({"msh2", "msh2"}).same_file);
}

// With split crossings both pieces of a split segment are numbered as the
// file's segment; the markers are read by validated segment, before that.
TEST(MeshOutput, SplitCrossingsNumberEdgesByTheFilesSegment) {
  Pslg input = two_squares_input();
  input.segment_origin = {3, 5};
  Mesh split = two_squares();
  const MeshLabels labels = label_refined_mesh(split, input, DomainOptions{false, true});
  EXPECT_EQ(labels.edge_markers, (std::vector<int>{7, 0}));
  EXPECT_EQ(split.constrained_edges[0].segment, 3);
  EXPECT_EQ(split.constrained_edges[1].segment, 5);
  Mesh kept = two_squares();
  label_refined_mesh(kept, input, DomainOptions{});
  EXPECT_EQ(kept.constrained_edges[0].segment, 0);
  EXPECT_EQ(kept.constrained_edges[1].segment, 1);
}

TEST(MeshOutput, WritesEachFormatAndTheUnimprovableList) {
  // Per process: other checkouts may run the same tests at the same time.
  const std::string prefix =
      (std::filesystem::temp_directory_path() / ("lepp_mesh_output_test_" + std::to_string(::getpid()))).string();
  UnimprovableTriangle u;
  u.triangle = {0, 1, 4};
  write_refined_mesh(prefix, two_squares(), {}, {u}, {MeshFormat::Vtu, MeshFormat::Msh2});
  for (const char* ext : {".vtu", ".msh", ".unimprovable"}) {
    EXPECT_TRUE(std::filesystem::exists(prefix + ext)) << ext;
  }
  EXPECT_FALSE(std::filesystem::exists(prefix + ".node"));
  write_refined_mesh(prefix, two_squares(), {}, {}, {});  // no list: an old one is removed
  EXPECT_FALSE(std::filesystem::exists(prefix + ".unimprovable"));
  for (const char* ext : {".vtu", ".msh"}) std::filesystem::remove(prefix + ext);
}

TEST(MeshFormats, LabelsOfTheWrongSizeAreRejected) {
  const std::string dir = std::filesystem::temp_directory_path().string();
  MeshLabels bad;
  bad.triangle_regions = {1, 2};
  EXPECT_THROW(write_vtu(dir + "/lepp_bad.vtu", two_squares(), bad), std::invalid_argument);
  EXPECT_THROW(write_msh4(dir + "/lepp_bad.msh", two_squares(), bad), std::invalid_argument);
  MeshLabels bad_markers;
  bad_markers.edge_markers = {1};
  EXPECT_THROW(write_msh2(dir + "/lepp_bad.msh", two_squares(), bad_markers), std::invalid_argument);
}

TEST(MeshFormats, AnUnwritablePathThrowsNamingIt) {
  for (MeshFormat f : {MeshFormat::Vtu, MeshFormat::Msh2, MeshFormat::Msh4}) {
    try {
      write_mesh("/nonexistent-dir/out", two_squares(), f, {});
      ADD_FAILURE() << to_string(f) << ": no exception";
    } catch (const std::system_error& e) {
      EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/out"), std::string::npos) << e.what();
    }
  }
}

TEST(MeshFormats, FullDiskIsReported) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  EXPECT_THROW(write_vtu("/dev/full", two_squares(), {}), std::system_error);
  EXPECT_THROW(write_msh4("/dev/full", two_squares(), {}, true), std::system_error);
}

// Every DataArray's offset points at a UInt64 byte count that matches its
// declared type and size, and the arrays tile the appended block exactly.
TEST(MeshFormats, VtuOffsetsMatchTheAppendedData) {
  const std::string path = (std::filesystem::temp_directory_path() / "lepp_offsets.vtu").string();
  const Mesh m = two_squares();
  write_vtu(path, m, mesh_labels(m, two_squares_input()));
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string file = ss.str();
  const std::size_t data = file.find("<AppendedData encoding=\"raw\">");
  ASSERT_NE(data, std::string::npos);
  const std::size_t base = file.find('_', data) + 1;
  const std::regex array("<DataArray type=\"(\\w+)\" Name=\"(\\w+)\"(?: NumberOfComponents=\"(\\d)\")? format=\"appended\" offset=\"(\\d+)\"/>");
  const std::map<std::string, std::size_t> size = {{"UInt8", 1}, {"Int32", 4}, {"Int64", 8}, {"Float64", 8}};
  const std::map<std::string, std::size_t> tuples = {
      {"input", 7}, {"Points", 7}, {"connectivity", 15}, {"offsets", 5}, {"types", 5}};
  std::size_t expected_offset = 0, arrays = 0;
  for (auto it = std::sregex_iterator(file.begin(), file.begin() + static_cast<std::ptrdiff_t>(data), array);
       it != std::sregex_iterator(); ++it, ++arrays) {
    const std::string name = (*it)[2];
    const std::size_t components = (*it)[3].matched ? std::stoul((*it)[3]) : 1;
    const std::size_t offset = std::stoul((*it)[4]);
    EXPECT_EQ(offset, expected_offset) << name;
    std::uint64_t nbytes = 0;
    std::memcpy(&nbytes, file.data() + base + offset, sizeof nbytes);
    const std::size_t n = tuples.count(name) ? tuples.at(name) : 5;  // cell data: one per triangle
    EXPECT_EQ(nbytes, n * components * size.at((*it)[1])) << name;
    expected_offset = offset + 8 + nbytes;
  }
  EXPECT_EQ(arrays, 11u);
  EXPECT_EQ(file.compare(base + expected_offset, 3, "\n  "), 0);
  // The first triangle's smallest angle is 45 degrees, as lepp/stats.h computes it.
  const std::size_t min_angle = file.find("Name=\"min_angle\"");
  ASSERT_NE(min_angle, std::string::npos);
  const std::size_t at = std::stoul(file.substr(file.find("offset=\"", min_angle) + 8));
  double first = 0;
  std::memcpy(&first, file.data() + base + at + 8, sizeof first);
  EXPECT_EQ(first, min_angle_deg(m.vertices[0], m.vertices[1], m.vertices[4]));
  EXPECT_NEAR(first, 45, 1e-12);
}

TEST(TriangleQuality, EquilateralIsOneAndSliverIsFar) {
  const Point a{0, 0}, b{1, 0}, c{0.5, std::sqrt(3.0) / 2};
  EXPECT_NEAR(max_angle_deg(a, b, c), 60, 1e-12);
  EXPECT_NEAR(radius_ratio(a, b, c), 1, 1e-12);
  EXPECT_NEAR(edge_ratio(a, b, c), 1, 1e-12);
  const Point s{0.5, 0.01};
  EXPECT_GT(max_angle_deg(a, b, s), 170);
  EXPECT_LT(radius_ratio(a, b, s), 0.01);
  EXPECT_NEAR(edge_ratio(a, b, s), 1 / std::hypot(0.5, 0.01), 1e-12);
  // Right isosceles: angles 45 and 90, radius ratio 2 (sqrt 2 - 1), edge ratio sqrt 2.
  EXPECT_NEAR(max_angle_deg(a, b, {0, 1}), 90, 1e-12);
  EXPECT_NEAR(radius_ratio(a, b, {0, 1}), 2 * (std::sqrt(2.0) - 1), 1e-12);
  EXPECT_NEAR(edge_ratio(a, b, {0, 1}), std::sqrt(2.0), 1e-12);
}

}  // namespace
}  // namespace lepp
