// SPDX-License-Identifier: GPL-3.0-or-later
// The readers at the boundaries of their numbering rules (issue 22): a .poly
// with no vertices beside a 0-based .node, ids one past the last vertex, and a
// mesh's full .poly whose vertex lines are skipped. Each test names the
// mutants of tools/mutation/mutants.txt it kills.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "scratch_files.h"

#include "lepp/input.h"
#include "lepp/io.h"

namespace fs = std::filesystem;

namespace lepp {
namespace {

using ReaderBoundary = ScratchFiles;

// Kills core-node-beside-poly-one-based: the segments of a .poly with no
// vertices are numbered like the .node beside it, here from 0.
TEST_F(ReaderBoundary, EmptyPolyBesideZeroBasedNode) {
  write("sq.node", "4 2 0 0\n0 0 0\n1 4 0\n2 4 4\n3 0 4\n");
  const std::string poly = write("sq.poly", "0 2 0 0\n4 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n0\n");
  const Pslg p = read_poly(poly);
  ASSERT_EQ(p.vertices.size(), 4u);
  ASSERT_EQ(p.segments.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(p.segments[static_cast<std::size_t>(i)].a, i);
    EXPECT_EQ(p.segments[static_cast<std::size_t>(i)].b, (i + 1) % 4);
  }
  EXPECT_EQ(p.vertices[2].x, 4);
  EXPECT_EQ(p.vertices[2].y, 4);
}

// The same with a 1-based .node: the numbering moves with it (segment 0 is then out of order).
TEST_F(ReaderBoundary, EmptyPolyBesideOneBasedNode) {
  write("sq.node", "4 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n");
  const std::string poly = write("sq.poly", "0 2 0 0\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n");
  const Pslg p = read_poly(poly);
  ASSERT_EQ(p.segments.size(), 4u);
  EXPECT_EQ(p.segments[0].a, 0);
  EXPECT_EQ(p.segments[3].b, 0);
  const std::string zero = write("zero.poly", "0 2 0 0\n4 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n0\n");
  write("zero.node", "4 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n");
  EXPECT_THROW(read_poly(zero), InputError);
}

// Kills core-poly-segment-numbered-from-one: a 0-based .poly numbers its segments from 0.
TEST_F(ReaderBoundary, ZeroBasedPolyNumbersSegmentsFromZero) {
  const std::string poly = write("z.poly", "3 2 0 0\n0 0 0\n1 4 0\n2 0 4\n3 0\n0 0 1\n1 1 2\n2 2 0\n0\n");
  const Pslg p = read_poly(poly);
  ASSERT_EQ(p.segments.size(), 3u);
  EXPECT_EQ(p.segments[1].a, 1);
  EXPECT_EQ(p.segments[1].b, 2);
}

// Kills core-poly-endpoint-past-end: an endpoint one past the last vertex is an error naming the line.
TEST_F(ReaderBoundary, SegmentEndpointOnePastTheLastVertex) {
  const std::string ok = write("ok.poly", "3 2 0 0\n1 0 0\n2 4 0\n3 0 4\n1 0\n1 1 3\n0\n");
  EXPECT_EQ(read_poly(ok).segments.at(0).b, 2);
  const std::string bad = write("bad.poly", "3 2 0 0\n1 0 0\n2 4 0\n3 0 4\n1 0\n1 1 4\n0\n");
  try {
    read_poly(bad);
    FAIL() << "endpoint 4 of 3 vertices accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 6) << e.what();
  }
}

// Kills core-mesh-always-one-based: a mesh numbered from 0 (Triangle's -z) reads as it is.
TEST_F(ReaderBoundary, ZeroBasedMesh) {
  write("m.node", "4 2 0 0\n0 0 0\n1 4 0\n2 4 4\n3 0 4\n");
  write("m.ele", "2 3 0\n0 0 1 2\n1 0 2 3\n");
  const Mesh m = read_mesh((dir_ / "m").string());
  ASSERT_EQ(m.triangles.size(), 2u);
  EXPECT_EQ(m.triangles[0], (Tri{0, 1, 2}));
  EXPECT_EQ(m.triangles[1], (Tri{0, 2, 3}));
}

// Kills core-mesh-vertex-id-past-end: a triangle naming the vertex one past the last is an error.
TEST_F(ReaderBoundary, MeshVertexIdOnePastTheLast) {
  write("m.node", "3 2 0 0\n1 0 0\n2 4 0\n3 0 4\n");
  write("m.ele", "1 3 0\n1 1 2 3\n");
  EXPECT_EQ(read_mesh((dir_ / "m").string()).triangles.size(), 1u);
  write("m.ele", "1 3 0\n1 1 2 4\n");
  EXPECT_THROW(read_mesh((dir_ / "m").string()), InputError);
}

// Kills core-mesh-poly-vertex-lines-one-short: a mesh's .poly with its vertex
// section (as Triangle writes with -p) has them skipped, the segments read after.
TEST_F(ReaderBoundary, MeshFullPolyVertexLinesSkipped) {
  write("m.node", "3 2 0 0\n1 0 0\n2 4 0\n3 0 4\n");
  write("m.ele", "1 3 0\n1 1 2 3\n");
  write("m.poly", "3 2 0 0\n1 0 0\n2 4 0\n3 0 4\n3 0\n1 1 2\n2 2 3\n3 3 1\n0\n");
  const Mesh m = read_mesh((dir_ / "m").string());
  ASSERT_EQ(m.constrained_edges.size(), 3u);
  EXPECT_EQ(m.constrained_edges[2].a, 2);
  EXPECT_EQ(m.constrained_edges[2].b, 0);
}

}  // namespace
}  // namespace lepp

namespace lepp {
namespace {

// The numbers' fast path (std::from_chars) and the strtod/strtoll path it falls back to
// give the same values and the same errors: a sign '+', hexadecimal, a decimal point
// without digits on one side, subnormals, underflow to zero, overflow, inf and nan,
// integers with '+' and beyond 64 bits. Each row: a coordinate (or a vertex number) as
// written, and the value read, or the error's words.
TEST_F(ReaderBoundary, NumberTokensReadAsStrtodReadsThem) {
  struct Row {
    const char* token;
    double value;         // read
    const char* error;    // or this error (nullptr: none)
  };
  const Row rows[] = {
      {"1.5", 1.5, nullptr},          {"+1.5", 1.5, nullptr},       {"-0", -0.0, nullptr},
      {".5", 0.5, nullptr},           {"5.", 5.0, nullptr},         {"1e3", 1000.0, nullptr},
      {"1E-3", 1e-3, nullptr},        {"0x10", 16.0, nullptr},      {"0x1p-3", 0.125, nullptr},
      {"4.9e-324", 4.9e-324, nullptr}, {"1e-400", 0.0, nullptr},    {"2.2250738585072011e-308", 2.2250738585072011e-308, nullptr},
      {"1e400", 0, "too large"},       {"inf", 0, "not finite"},    {"nan", 0, "not finite"},
      {"1e", 0, "not a number"},       {"1.5x", 0, "not a number"}, {"--1", 0, "not a number"},
  };
  for (const Row& r : rows) {
    const std::string node = write("v.node", std::string("1 2 0 0\n1 ") + r.token + " 2\n");
    try {
      const Pslg p = read_node(node);
      ASSERT_EQ(r.error, nullptr) << r.token << " was read as " << p.vertices[0].x;
      EXPECT_EQ(p.vertices[0].x, r.value) << r.token;
      EXPECT_EQ(std::signbit(p.vertices[0].x), std::signbit(r.value)) << r.token;
    } catch (const InputError& e) {
      ASSERT_NE(r.error, nullptr) << r.token << ": " << e.what();
      EXPECT_NE(std::string(e.what()).find(r.error), std::string::npos) << r.token << ": " << e.what();
      EXPECT_EQ(e.line(), 2) << r.token;
    }
  }
  // Integers: '+' and leading zeros read as strtoll reads them; beyond 64 bits an error.
  EXPECT_EQ(read_node(write("p.node", "+1 2 0 0\n+1 0 0\n")).vertices.size(), 1u);
  EXPECT_EQ(read_node(write("z.node", "001 2 0 0\n0001 0 0\n")).vertices.size(), 1u);
  EXPECT_THROW(read_node(write("big.node", "99999999999999999999 2 0 0\n1 0 0\n")), InputError);
}

}  // namespace
}  // namespace lepp
