// SPDX-License-Identifier: GPL-3.0-or-later
// Writers round-trip through the readers: write_mesh then read_mesh gives the
// same mesh with bit-identical coordinates; write_poly then read_poly the same
// PSLG; the .node and .ele are fmt's text across the writer's blocks; and the mesh
// reader rejects a broken file.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <string>

#include <fmt/format.h>

#include "lepp/io.h"
#include "lepp/node_text_stream.h"

namespace lepp {
namespace {

std::uint64_t bits(double d) {
  std::uint64_t b;
  std::memcpy(&b, &d, sizeof b);
  return b;
}

std::string temp_prefix(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("lepp_core_test_" + name + "_" + std::to_string(::getpid()))).string();
}

// Awkward doubles: random bit patterns of every magnitude, subnormals, -0, extremes.
std::vector<Point> awkward_points(std::size_t n) {
  std::mt19937_64 rng(20261122);
  std::vector<Point> pts = {{-0.0, 0.0},
                            {std::numeric_limits<double>::denorm_min(), -std::numeric_limits<double>::max()},
                            {std::numeric_limits<double>::min(), 1e-300},
                            {0.1, 1.0 / 3.0}};
  while (pts.size() < n) {
    double d[2];
    for (double& x : d) {
      do {
        std::uint64_t b = rng();
        std::memcpy(&x, &b, sizeof x);
      } while (!std::isfinite(x));
    }
    pts.push_back({d[0], d[1]});
  }
  return pts;
}

TEST(MeshIo, WriteThenReadIsBitIdentical) {
  Mesh mesh;
  mesh.vertices = awkward_points(200);
  mesh.input_vertices = 120;
  for (int i = 0; i + 2 < 200; i += 3) mesh.triangles.push_back({i, i + 1, i + 2});
  for (int i = 0; i + 1 < 200; i += 7) mesh.constrained_edges.push_back({i, i + 1, i % 5});
  const std::string prefix = temp_prefix("mesh");
  write_mesh(prefix, mesh);
  Mesh back = read_mesh(prefix);
  ASSERT_EQ(back.vertices.size(), mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    EXPECT_EQ(bits(back.vertices[i].x), bits(mesh.vertices[i].x)) << i;
    EXPECT_EQ(bits(back.vertices[i].y), bits(mesh.vertices[i].y)) << i;
  }
  EXPECT_EQ(back.triangles, mesh.triangles);
  ASSERT_EQ(back.constrained_edges.size(), mesh.constrained_edges.size());
  for (std::size_t i = 0; i < mesh.constrained_edges.size(); ++i) {
    EXPECT_EQ(back.constrained_edges[i].a, mesh.constrained_edges[i].a);
    EXPECT_EQ(back.constrained_edges[i].b, mesh.constrained_edges[i].b);
  }
  for (const char* ext : {".node", ".ele", ".poly"}) std::filesystem::remove(prefix + ext);
}

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// threads > 1 writes the .node on a second thread: the same three files, byte for byte.
std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The .node's and .ele's lines are formatted straight into the writer's 1 MiB blocks:
// over several blocks, with the longest doubles there are, the text is fmt's, line by line.
TEST(MeshIo, NodeAndEleLinesAreFmtsTextAcrossBlocks) {
  Mesh mesh;
  mesh.vertices = awkward_points(60000);  // about 3 MiB of .node
  mesh.input_vertices = 1000;
  std::mt19937 rng(40);
  for (int i = 0; i < 150000; ++i)
    mesh.triangles.push_back({static_cast<int>(rng() % 60000), static_cast<int>(rng() % 60000), static_cast<int>(rng() % 60000)});
  std::string node = fmt::format("# lepp mesh: marker 1 = input vertex, 0 = Steiner point\n{} 2 0 1\n", mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    node += fmt::format("{} {} {} {}\n", i + 1, mesh.vertices[i].x, mesh.vertices[i].y, i < mesh.input_vertices ? 1 : 0);
  std::string ele = fmt::format("{} 3 0\n", mesh.triangles.size());
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
    ele += fmt::format("{} {} {} {}\n", i + 1, mesh.triangles[i][0] + 1, mesh.triangles[i][1] + 1, mesh.triangles[i][2] + 1);
  ASSERT_GT(node.size(), std::size_t{3} << 20);
  ASSERT_GT(ele.size(), std::size_t{2} << 20);
  for (int threads : {1, 2}) {
    const std::string prefix = temp_prefix("blocks" + std::to_string(threads));
    write_mesh(prefix, mesh, threads);
    EXPECT_TRUE(file_text(prefix + ".node") == node) << threads << " thread(s)";
    EXPECT_TRUE(file_text(prefix + ".ele") == ele) << threads << " thread(s)";
    for (const char* ext : {".node", ".ele", ".poly"}) std::filesystem::remove(prefix + ext);
  }
}

TEST(MeshIo, TwoThreadsWriteTheSameFiles) {
  Mesh mesh;
  mesh.vertices = awkward_points(3000);
  mesh.input_vertices = 700;
  for (int i = 0; i + 2 < 3000; i += 3) mesh.triangles.push_back({i, i + 2, i + 1});
  for (int i = 0; i + 1 < 3000; i += 11) mesh.constrained_edges.push_back({i, i + 1, i % 9});
  const std::string one = temp_prefix("one_thread"), two = temp_prefix("two_threads");
  write_mesh(one, mesh, 1);
  write_mesh(two, mesh, 2);
  for (const char* ext : {".node", ".ele", ".poly"}) {
    const std::string a = file_bytes(one + ext);
    EXPECT_FALSE(a.empty()) << ext;
    EXPECT_EQ(a, file_bytes(two + ext)) << ext;
    std::filesystem::remove(one + ext);
    std::filesystem::remove(two + ext);
  }
}

// Where no file can be written, both threads fail: one InputError naming the prefix,
// never std::terminate from an exception left in a thread.
TEST(MeshIo, TwoThreadsThatCannotWriteThrowOneInputError) {
  Mesh mesh;
  mesh.vertices = awkward_points(10);
  mesh.triangles.push_back({0, 1, 2});
  const std::string prefix = "/nonexistent-lepp-directory/mesh";
  for (int threads : {1, 2}) {
    try {
      write_mesh(prefix, mesh, threads);
      ADD_FAILURE() << "no error with " << threads << " threads";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(prefix), std::string::npos) << e.what();
    }
  }
}

// n awkward points, the first `inputs` of them the input's, and one triangle: enough
// for a .node.
Mesh points_mesh(std::size_t n, std::size_t inputs) {
  Mesh mesh;
  mesh.vertices = awkward_points(n);
  mesh.input_vertices = inputs;
  mesh.triangles.push_back({0, 1, 2});
  return mesh;
}

void remove_mesh_files(const std::string& prefix) {
  for (const char* ext : {".node", ".ele", ".poly"}) std::filesystem::remove(prefix + ext);
}

// The .node's lines made beside the refinement (node_text_stream.h): handed over in
// growing prefixes, as the engine does, then the header, the copied lines and the
// rest formatted: the bytes of a .node written whole. 60,000 awkward points are
// about 3 MiB of text: the stream's thread writes several blocks, and the copy
// crosses the writer's own.
TEST(NodeTextStream, StreamedNodeIsTheWholeWritesBytes) {
  Mesh mesh;
  mesh.vertices = awkward_points(60000);
  mesh.input_vertices = 1000;
  for (int i = 0; i + 2 < 60000; i += 3) mesh.triangles.push_back({i, i + 2, i + 1});
  const std::string whole = temp_prefix("whole");
  write_mesh(whole, mesh, 1);
  const std::string expected = file_bytes(whole + ".node");
  // Handed over: nothing, some, all but a tail, all (each then written with one and two threads).
  for (std::size_t handed : {std::size_t{0}, std::size_t{3}, std::size_t{41000}, std::size_t{59993}, std::size_t{60000}})
    for (int threads : {1, 2}) {
      const std::string prefix = temp_prefix("streamed");
      std::unique_ptr<NodeTextStream> stream = NodeTextStream::open(prefix);
      ASSERT_TRUE(stream);
      for (std::size_t n : {handed / 3, handed / 3, handed / 2, handed}) {  // one hand-over of nothing new
        std::vector<Point> prefix_points(mesh.vertices.begin(), mesh.vertices.begin() + static_cast<std::ptrdiff_t>(n));
        stream->add(prefix_points, mesh.input_vertices);
      }
      write_mesh(prefix, mesh, threads, stream.get());
      EXPECT_TRUE(file_bytes(prefix + ".node") == expected) << handed << " handed over, " << threads << " thread(s)";
      EXPECT_EQ(file_bytes(prefix + ".ele"), file_bytes(whole + ".ele"));
      EXPECT_EQ(stream->finish(mesh.input_vertices).lines, handed);  // finish again: the same answer
      remove_mesh_files(prefix);
    }
  remove_mesh_files(whole);
}

// The lines copied are the stream's, not formatted again: a vertex handed over with
// other coordinates than the mesh's shows in the file. (The engine never does this;
// the test tells that the copy is what writes those lines.)
TEST(NodeTextStream, TheHandedOverLinesAreTheOnesWritten) {
  const Mesh mesh = points_mesh(100, 10);
  const std::string prefix = temp_prefix("copied");
  std::unique_ptr<NodeTextStream> stream = NodeTextStream::open(prefix);
  ASSERT_TRUE(stream);
  std::vector<Point> handed(mesh.vertices.begin(), mesh.vertices.begin() + 50);
  handed[20] = {1.5, -2.25};
  stream->add(handed, mesh.input_vertices);
  write_mesh(prefix, mesh, 1, stream.get());
  const std::string node = file_bytes(prefix + ".node");
  EXPECT_NE(node.find("\n21 1.5 -2.25 0\n"), std::string::npos);
  EXPECT_NE(node.find(fmt::format("\n51 {} {} 0\n", mesh.vertices[50].x, mesh.vertices[50].y)), std::string::npos);
  remove_mesh_files(prefix);
}

// Lines whose markers were made for another count of input vertices are not used:
// the .node is formatted whole, with the mesh's markers.
TEST(NodeTextStream, AnotherInputVertexCountIsNotUsed) {
  const Mesh mesh = points_mesh(200, 30);
  const std::string whole = temp_prefix("markers_whole");
  write_mesh(whole, mesh, 1);
  for (int differ : {0, 1}) {  // the count differs from the mesh's, or between two hand-overs
    const std::string prefix = temp_prefix("markers");
    std::unique_ptr<NodeTextStream> stream = NodeTextStream::open(prefix);
    ASSERT_TRUE(stream);
    std::vector<Point> half(mesh.vertices.begin(), mesh.vertices.begin() + 100);
    stream->add(half, differ ? 30 : 29);
    stream->add(mesh.vertices, 29);
    write_mesh(prefix, mesh, 2, stream.get());
    EXPECT_EQ(file_bytes(prefix + ".node"), file_bytes(whole + ".node")) << differ;
    EXPECT_EQ(stream->finish(mesh.input_vertices).lines, 0u) << differ;
    remove_mesh_files(prefix);
  }
  remove_mesh_files(whole);
}

// A run that ends without writing (an error, a capacity stop) drops its stream: the
// thread stops and the temporary file goes, with blocks still waiting. Where no
// temporary file can be made, there is no stream.
TEST(NodeTextStream, DroppedUnfinishedAndUnopenable) {
  const std::vector<Point> pts = awkward_points(50000);
  for (int i = 0; i < 20; ++i) {
    std::unique_ptr<NodeTextStream> stream = NodeTextStream::open(temp_prefix("dropped"));
    ASSERT_TRUE(stream);
    for (std::size_t n = 1000; n <= pts.size(); n += 7000)
      stream->add(std::vector<Point>(pts.begin(), pts.begin() + static_cast<std::ptrdiff_t>(n)), 5);
  }
  EXPECT_FALSE(NodeTextStream::open("/nonexistent-lepp-directory/mesh"));
}

TEST(MeshIo, WritePolyThenReadPoly) {
  Pslg p;
  p.vertices = awkward_points(50);
  p.vertex_markers.assign(50, 3);
  for (int i = 0; i + 1 < 50; ++i) p.segments.push_back({i, i + 1, i});
  p.holes = {{0.25, -1e-310}};
  const std::string path = temp_prefix("pslg") + ".poly";
  write_poly(path, p);
  Pslg back = read_poly(path);
  ASSERT_EQ(back.vertices.size(), p.vertices.size());
  for (std::size_t i = 0; i < p.vertices.size(); ++i) {
    EXPECT_EQ(bits(back.vertices[i].x), bits(p.vertices[i].x));
    EXPECT_EQ(bits(back.vertices[i].y), bits(p.vertices[i].y));
  }
  EXPECT_EQ(back.vertex_markers, p.vertex_markers);
  ASSERT_EQ(back.segments.size(), p.segments.size());
  for (std::size_t i = 0; i < p.segments.size(); ++i) {
    EXPECT_EQ(back.segments[i].a, p.segments[i].a);
    EXPECT_EQ(back.segments[i].b, p.segments[i].b);
    EXPECT_EQ(back.segments[i].marker, p.segments[i].marker);
  }
  ASSERT_EQ(back.holes.size(), 1u);
  EXPECT_EQ(bits(back.holes[0].y), bits(-1e-310));
  std::filesystem::remove(path);
}

TEST(MeshIo, UnimprovableRoundTrip) {
  const std::string prefix = temp_prefix("unimp");
  std::vector<UnimprovableTriangle> list = {{{0, 1, 2}, 0, 3, 4, 12.5}, {{5, 6, 7}, 6, 1, 2, 0.75}};
  write_unimprovable(prefix, list);
  std::vector<UnimprovableTriangle> back = read_unimprovable(prefix);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[1].triangle, list[1].triangle);
  EXPECT_EQ(back[1].apex, 6);
  EXPECT_EQ(back[0].segment2, 4);
  EXPECT_EQ(back[1].input_angle_deg, 0.75);
  write_unimprovable(prefix, {});  // an empty list removes the file
  EXPECT_TRUE(read_unimprovable(prefix).empty());
}

TEST(MeshIo, BrokenEleIsAnInputError) {
  Mesh mesh;
  mesh.vertices = {{0, 0}, {1, 0}, {0, 1}};
  mesh.triangles = {{0, 1, 2}};
  const std::string prefix = temp_prefix("broken");
  write_mesh(prefix, mesh);
  std::ofstream(prefix + ".ele") << "1 3 0\n1 1 2 4\n";  // vertex 4 does not exist
  try {
    read_mesh(prefix);
    FAIL() << "accepted an out-of-range triangle corner";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_NE(std::string(e.what()).find("out of range"), std::string::npos);
  }
  std::ofstream(prefix + ".ele") << "1000000000000 3 0\n1 1 2 3\n";  // a lying header
  EXPECT_THROW(read_mesh(prefix), InputError);
  for (const char* ext : {".node", ".ele", ".poly"}) std::filesystem::remove(prefix + ext);
}

}  // namespace
}  // namespace lepp

namespace lepp {
namespace {

TEST(MeshIo, UnimprovableWithBadIdsIsAnInputError) {
  const std::string prefix = temp_prefix("unimp_bad");
  std::ofstream(prefix + ".unimprovable") << "1\n1 2 3 0 1 2 5.0\n";  // apex 0 in a 1-based file
  EXPECT_THROW(read_unimprovable(prefix), InputError);
  std::filesystem::remove(prefix + ".unimprovable");
}

}  // namespace
}  // namespace lepp
