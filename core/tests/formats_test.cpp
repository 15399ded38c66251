// SPDX-License-Identifier: GPL-3.0-or-later
// Reading as Triangle does (issue 12): a column of extra fields ignored with
// one warning, optional fields missing read as 0, regions kept, a .node alone,
// the convex hull of a point set, crossing segments split at the rounded
// exact intersection, a bare prefix read as Triangle reads one.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <utility>

#include <unistd.h>

#include "lepp/input.h"
#include "lepp/io.h"
#include "lepp/validate.h"

namespace lepp {
namespace {

const std::string kFormats = LEPP_SOURCE_DIR "/corpus/triangle-formats/";

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = (std::filesystem::temp_directory_path() / ("lepp-formats-" + name)).string();
  std::ofstream(path) << text;
  return path;
}

std::size_t count_containing(const std::vector<std::string>& lines, const std::string& fragment) {
  return static_cast<std::size_t>(
      std::count_if(lines.begin(), lines.end(), [&](const std::string& w) { return w.find(fragment) != std::string::npos; }));
}

TEST(TriangleFormats, MarkerColumnIsIgnoredWithOneWarningNamingTheFirstLine) {
  std::vector<std::string> warnings;
  Pslg p = read_poly(kFormats + "marker-column.poly", warnings);
  EXPECT_EQ(p.vertices.size(), 8u);
  ASSERT_EQ(p.segments.size(), 8u);
  EXPECT_EQ(p.segments[7].a, 7);
  EXPECT_EQ(p.segments[7].marker, 0);  // the header says no markers: the column is not read
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("marker-column.poly:14: extra fields"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("8 lines"), std::string::npos) << warnings[0];
}

TEST(TriangleFormats, StrayExtraFieldIsStillAnError) {
  // Only one segment line of four carries an extra field: a typo, not a column.
  const std::string path = write_temp("stray.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 2 3 9\n3 3 1\n");
  try {
    read_poly(path);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 7);
    EXPECT_NE(std::string(e.what()).find("extra fields"), std::string::npos) << e.what();
  }
}

TEST(TriangleFormats, MissingMarkerReadsAsZero) {
  std::vector<std::string> warnings;
  const std::string path = write_temp("short.poly", "3 2 1 1\n1 0 0 7 2\n2 1 0 7\n3 0 1\n3 1\n1 1 2 5\n2 2 3\n3 3 1 5\n");
  Pslg p = read_poly(path, warnings);
  EXPECT_EQ(p.vertex_markers, (std::vector<int>{2, 0, 0}));
  EXPECT_EQ(p.segments[1].marker, 0);
  EXPECT_EQ(p.segments[2].marker, 5);
  EXPECT_EQ(count_containing(warnings, "read as 0"), 1u);
  EXPECT_NE(warnings[0].find(":3:"), std::string::npos) << warnings[0];
}

TEST(TriangleFormats, RegionsAreKept) {
  std::vector<std::string> warnings;
  Pslg p = read_poly(kFormats + "regions.poly", warnings);
  ASSERT_EQ(p.regions.size(), 2u);
  EXPECT_EQ(p.regions[0].at, (Point{2.0, 3.0}));
  EXPECT_EQ(p.regions[0].attribute, 1.0);
  EXPECT_EQ(p.regions[0].max_area, 0.5);
  EXPECT_EQ(p.regions[1].attribute, 2.0);
  EXPECT_EQ(p.regions[1].max_area, 2.0);  // one value: attribute and area bound, as Triangle reads it
  EXPECT_EQ(p.region_lines, (std::vector<int>{22, 23}));
  EXPECT_TRUE(warnings.empty());
  Pslg v = validate(p, warnings);
  EXPECT_EQ(v.regions.size(), 2u);
  // write_poly keeps them.
  const std::string path = write_temp("regions-back.poly", "");
  write_poly(path, p);
  Pslg back = read_poly(path);
  ASSERT_EQ(back.regions.size(), 2u);
  EXPECT_EQ(back.regions[1].at, p.regions[1].at);
  EXPECT_EQ(back.regions[1].max_area, 2.0);
}

TEST(TriangleFormats, ZeroBasedAndAttributes) {
  std::vector<std::string> warnings;
  Pslg z = read_poly(kFormats + "zero-based.poly", warnings);
  EXPECT_EQ(z.segments[4].a, 4);
  EXPECT_EQ(z.segments[4].b, 0);
  Pslg a = read_poly(kFormats + "attributes.poly", warnings);
  EXPECT_EQ(a.vertices[5], (Point{3.3, 2.9}));
  EXPECT_EQ(a.vertex_markers[5], 0);
  EXPECT_EQ(a.segments[0].marker, 4);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
}

TEST(TriangleFormats, ANodeAloneMeshesItsConvexHull) {
  std::vector<std::string> warnings;
  Pslg p = read_input(kFormats + "points.node", warnings);
  EXPECT_EQ(p.vertices.size(), 12u);
  EXPECT_TRUE(p.segments.empty());
  EXPECT_THROW(validate(p, warnings), InputError);  // plain validate(): no domain
  Pslg v = validate(p, DomainOptions{}, warnings);
  EXPECT_EQ(v.segments.size(), 7u);  // the hull of points.node has 7 vertices
  EXPECT_TRUE(warnings.empty()) << warnings.front();
}

TEST(TriangleFormats, HullKeepsCollinearBoundaryVertices) {
  Pslg p;
  p.vertices = {{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}, {0, 1}, {0, 0}};
  std::vector<Segment> hull = convex_hull_segments(p);
  EXPECT_EQ(hull.size(), 6u);  // (1,0) and (0,1) lie on hull edges; (1,1) inside; the duplicate once
  std::vector<std::string> warnings;
  Pslg v = validate(p, DomainOptions{}, warnings);
  EXPECT_EQ(v.segments.size(), 6u);
  EXPECT_EQ(count_containing(warnings, "passes through"), 0u);
}

TEST(TriangleFormats, ConvexHullClosesAnOpenBoundary) {
  std::vector<std::string> warnings;
  Pslg p = read_poly(kFormats + "open-boundary.poly", warnings);
  EXPECT_THROW(validate(p, warnings), InputError);
  DomainOptions hull;
  hull.convex_hull = true;
  Pslg v = validate(p, hull, warnings);
  EXPECT_EQ(v.segments.size(), 5u + 5u);  // the polyline (4), the inner segment, the 5 hull edges
  EXPECT_EQ(v.segment_origin.size(), v.segments.size());
}

TEST(TriangleFormats, CrossingsSplitAtTheRoundedExactIntersection) {
  // y = x/3 meets y = 1 - x/2 at (6/5, 2/5): the nearest doubles are 1.2 and 0.4.
  Pslg p;
  p.vertices = {{0, 0}, {3, 1}, {0, 1}, {2, 0}};
  p.segments = {{0, 1, 7}, {2, 3, 8}};
  std::vector<std::string> warnings;
  EXPECT_EQ(split_crossings(p, warnings), 1u);
  ASSERT_EQ(p.vertices.size(), 5u);
  EXPECT_EQ(p.vertices[4], (Point{1.2, 0.4}));
  ASSERT_EQ(p.segments.size(), 4u);
  EXPECT_EQ(p.segments[0].a, 0);
  EXPECT_EQ(p.segments[0].b, 4);
  EXPECT_EQ(p.segments[1].a, 4);
  EXPECT_EQ(p.segments[1].b, 1);
  EXPECT_EQ(p.segments[1].marker, 7);
  EXPECT_EQ(p.segments[3].marker, 8);
  EXPECT_EQ(p.segment_origin, (std::vector<int>{0, 0, 1, 1}));
}

TEST(TriangleFormats, CrossingPolygonsRejectedByDefaultSplitOnRequest) {
  std::vector<std::string> warnings;
  Pslg p = read_poly(kFormats + "crossing.poly", warnings);
  try {
    validate(p, DomainOptions{}, warnings);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("segments "), std::string::npos) << what;
    EXPECT_NE(what.find("--split-crossings"), std::string::npos) << what;
  }
  DomainOptions split;
  split.split_crossings = true;
  Pslg v = validate(p, split, warnings);
  EXPECT_EQ(v.vertices.size(), 16u);  // 8 crossings, as Triangle finds
  EXPECT_EQ(v.segments.size(), 24u);
  for (std::size_t s = 0; s < v.segments.size(); ++s) EXPECT_EQ(v.segment_origin[s], static_cast<int>(s / 3));
}

// A fresh directory of its own for each test of a bare prefix (and each
// process: worktrees share /tmp), holding copies of corpus files under the
// names the test gives them; removed at the end of the test.
struct ScratchDir {
  std::string path;
  explicit ScratchDir(const std::string& name) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("lepp-formats-prefix-" + std::to_string(::getpid()) + "-" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    path = dir.string() + "/";
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
};

void copy_corpus(const std::string& corpus_name, const std::string& to) {
  std::filesystem::copy_file(kFormats + corpus_name, to, std::filesystem::copy_options::overwrite_existing);
}

// The error reading `path` as lepp refine reads it stops with; the test fails
// when it reads.
InputError read_error(const std::string& path) {
  std::vector<std::string> warnings;
  try {
    read_input(path, warnings);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << path << ": accepted";
  return InputError(path, 0, "accepted");
}

// The bare prefix `x` of the scratch directory, read as lepp refine reads it
// (its warnings dropped), once the corpus files are copied there: {corpus name,
// name in the directory}.
Pslg read_x_among(const ScratchDir& scratch, std::initializer_list<std::pair<const char*, const char*>> files) {
  for (const auto& [corpus_name, name] : files) copy_corpus(corpus_name, scratch.path + name);
  std::vector<std::string> warnings;
  return read_input(scratch.path + "x", warnings);
}

TEST(TriangleFormats, BarePrefixReadsThePoly) {
  const ScratchDir scratch("poly");
  const Pslg p = read_x_among(scratch, {{"zero-based.poly", "x.poly"}});
  EXPECT_EQ(p.source, scratch.path + "x.poly");
  EXPECT_EQ(p.vertices.size(), 5u);
  EXPECT_EQ(p.segments.size(), 5u);
}

TEST(TriangleFormats, BarePrefixReadsTheNodeWhenThereIsNoPoly) {
  const ScratchDir scratch("node");
  const Pslg p = read_x_among(scratch, {{"points.node", "x.node"}});
  EXPECT_EQ(p.source, scratch.path + "x.node");
  EXPECT_EQ(p.vertices.size(), 12u);
  EXPECT_TRUE(p.segments.empty());
}

TEST(TriangleFormats, BarePrefixPrefersThePolyToTheNode) {
  const ScratchDir scratch("both");
  const Pslg p = read_x_among(scratch, {{"zero-based.poly", "x.poly"}, {"points.node", "x.node"}});
  EXPECT_EQ(p.source, scratch.path + "x.poly");
  EXPECT_EQ(p.vertices.size(), 5u);  // the .poly's own vertices, not the .node's 12
  EXPECT_EQ(p.segments.size(), 5u);
}

TEST(TriangleFormats, AnExistingFileIsReadAsItIsNotAsAPrefix) {
  const ScratchDir scratch("existing");
  const Pslg p = read_x_among(scratch, {{"zero-based.poly", "x"}, {"attributes.poly", "x.poly"}});
  EXPECT_EQ(p.source, scratch.path + "x");
  EXPECT_EQ(p.vertices.size(), 5u);
}

TEST(TriangleFormats, BarePrefixWithNeitherFileNamesThePathAndBothFiles) {
  const ScratchDir scratch("neither");
  const std::string& dir = scratch.path;
  const InputError neither = read_error(dir + "x");
  const std::string what = neither.what();
  EXPECT_EQ(neither.file(), dir + "x");
  EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  EXPECT_NE(what.find(dir + "x.poly"), std::string::npos) << what;
  EXPECT_NE(what.find(dir + "x.node"), std::string::npos) << what;
  // A missing name with an extension is not a prefix: x.poly.poly is not tried.
  copy_corpus("zero-based.poly", dir + "y.poly.poly");
  const InputError missing = read_error(dir + "y.poly");
  EXPECT_EQ(missing.file(), dir + "y.poly");
  EXPECT_NE(std::string(missing.what()).find("cannot open"), std::string::npos) << missing.what();
}

TEST(TriangleFormats, ADirectoryIsAPrefixNotAFile) {
  // `lepp refine box` with a directory box/ beside box.poly reads box.poly.
  const ScratchDir scratch("directory");
  const std::string& dir = scratch.path;
  std::filesystem::create_directory(dir + "x");
  const std::string what = read_error(dir + "x").what();
  EXPECT_NE(what.find("is a directory"), std::string::npos) << what;
  EXPECT_NE(what.find(dir + "x.node"), std::string::npos) << what;
  const Pslg p = read_x_among(scratch, {{"zero-based.poly", "x.poly"}});
  EXPECT_EQ(p.source, dir + "x.poly");
  // Named as a file, a directory is an error that says so.
  std::filesystem::create_directory(dir + "d.poly");
  const std::string file = read_error(dir + "d.poly").what();
  EXPECT_NE(file.find("is a directory"), std::string::npos) << file;
}

}  // namespace
}  // namespace lepp
