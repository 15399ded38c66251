// SPDX-License-Identifier: GPL-3.0-or-later
// The .poly/.node reader on good files: numbering, comments, attributes,
// markers, holes, regions, CRLF, a .poly taking its vertices from the .node.
#include <gtest/gtest.h>

#include "lepp/io.h"
#include "lepp/validate.h"

namespace lepp {
namespace {

const std::string kData = LEPP_SOURCE_DIR "/core/tests/data/";

TEST(ReadPoly, PaperSquare400) {
  Pslg p = read_poly(LEPP_SOURCE_DIR "/corpus/paper/square400.poly");
  EXPECT_EQ(p.vertices.size(), 400u);
  EXPECT_EQ(p.segments.size(), 400u);
  EXPECT_TRUE(p.holes.empty());
}

TEST(ReadPoly, PaperCirclesHasOneHole) {
  Pslg p = read_poly(LEPP_SOURCE_DIR "/corpus/paper/circles240.poly");
  EXPECT_EQ(p.vertices.size(), 240u);
  EXPECT_EQ(p.holes.size(), 1u);
}

TEST(ReadPoly, ZeroBasedWithMarkers) {
  Pslg p = read_poly(kData + "zero-based.poly");
  ASSERT_EQ(p.vertices.size(), 4u);
  EXPECT_EQ(p.vertices[2], (Point{1, 1}));
  ASSERT_EQ(p.segments.size(), 4u);
  EXPECT_EQ(p.segments[3].a, 3);  // "3 3 0": 0-based ids stay as they are
  EXPECT_EQ(p.segments[3].b, 0);
  EXPECT_EQ(p.segments[3].marker, 8);
  EXPECT_EQ(p.vertex_markers, (std::vector<int>{1, 1, 1, 1}));
  EXPECT_EQ(p.segment_lines[0], 8);  // lines are 1-based and count comments
}

TEST(ReadPoly, AttributesCommentsHolesRegions) {
  Pslg p = read_poly(kData + "attributes-comments.poly");
  ASSERT_EQ(p.vertices.size(), 7u);
  EXPECT_EQ(p.vertices[3], (Point{0, 2}));
  EXPECT_TRUE(p.vertex_markers.empty());
  ASSERT_EQ(p.segments.size(), 7u);
  EXPECT_EQ(p.segments[0].a, 0);  // "1 1 2": 1-based in the file
  EXPECT_EQ(p.segments[0].b, 1);
  ASSERT_EQ(p.holes.size(), 1u);
  EXPECT_EQ(p.holes[0], (Point{1, 1}));
  EXPECT_EQ(p.hole_lines[0], 21);
  std::vector<std::string> warnings;
  Pslg v = validate(p, warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  EXPECT_EQ(v.segments.size(), 7u);
}

TEST(ReadPoly, CrlfAndNoHoleSection) {
  Pslg p = read_poly(kData + "crlf-no-hole-section.poly");
  EXPECT_EQ(p.vertices.size(), 3u);
  EXPECT_EQ(p.segments.size(), 3u);
  EXPECT_TRUE(p.holes.empty());
}

TEST(ReadPoly, NoVerticesReadsTheNodeBeside) {
  Pslg p = read_poly(kData + "node-beside.poly");
  ASSERT_EQ(p.vertices.size(), 3u);
  EXPECT_EQ(p.vertices[1], (Point{4, 0}));
  EXPECT_EQ(p.vertex_markers, (std::vector<int>{2, 2, 2}));
  ASSERT_EQ(p.segments.size(), 3u);
  EXPECT_EQ(p.segments[2].a, 2);
  EXPECT_EQ(p.segments[2].b, 0);
  std::vector<std::string> warnings;
  EXPECT_NO_THROW(validate(p, warnings));
}

TEST(ReadNode, PointSet) {
  Pslg p = read_node(kData + "node-beside.node");
  EXPECT_EQ(p.vertices.size(), 3u);
  EXPECT_TRUE(p.segments.empty());
}

TEST(ReadPoly, MissingFileIsAnInputError) {
  EXPECT_THROW(read_poly(kData + "does-not-exist.poly"), InputError);
}

}  // namespace
}  // namespace lepp
