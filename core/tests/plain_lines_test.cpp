// SPDX-License-Identifier: GPL-3.0-or-later
// The readers' plain-line path (LineReader::plain: a .node vertex line or a .ele triangle
// line read in one pass, without tokens) and the general path it leaves every other line
// to: the same values, the same line numbers and the same first error, message for
// message, whichever path a line takes. Each file mixes lines of both kinds.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "scratch_files.h"

#include "lepp/input.h"
#include "lepp/io.h"
#include "lepp/mesh_read.h"

namespace fs = std::filesystem;

namespace lepp {
namespace {

class PlainLines : public ScratchFiles {
 protected:
  // The error read_node gives (its message without the path), or "" if none.
  std::string node_error(const std::string& text) {
    const std::string path = write("e.node", text);
    try {
      read_node(path);
    } catch (const InputError& e) {
      return std::string(e.what()).substr(path.size());
    }
    return "";
  }
  // The error read_mesh gives with `threads`, its path cut to the file's extension.
  std::string mesh_error(const std::string& node, const std::string& ele, int threads) {
    write("m.node", node);
    write("m.ele", ele);
    const std::string prefix = (dir_ / "m").string();
    try {
      read_mesh(prefix, threads);
    } catch (const InputError& e) {
      return std::string(e.what()).substr(prefix.size());
    }
    return "";
  }
};

// The same four vertices, plain and in forms the plain path leaves to the general one:
// a sign '+', hexadecimal, a comment after the last field or glued to it, blank and
// comment lines between, tabs, CRLF, 19 digits, no newline at the end.
TEST_F(PlainLines, PlainAndGeneralLinesReadAlike) {
  const std::string plain = "4 2 1 1\n1 0.5 -2.25 7 1\n2 3 4e-3 0 0\n3 -0 1e300 1 1\n4 1.5 2.5 0.125 0\n";
  const std::string general =
      "4 2 1 1\n"
      "+1 0x1p-1 -2.25 7 1 # comment\n"
      "\n# a comment line\n"
      "2\t3\t4e-3 0 0#glued\r\n"
      "0000000000000000003 -0 1e300 1 +1\n"
      "   4   1.5   2.5   0.125   0";
  const Pslg a = read_node(write("a.node", plain));
  const Pslg b = read_node(write("b.node", general));
  ASSERT_EQ(a.vertices.size(), 4u);
  ASSERT_EQ(b.vertices.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(a.vertices[i].x, b.vertices[i].x) << i;
    EXPECT_EQ(a.vertices[i].y, b.vertices[i].y) << i;
    EXPECT_EQ(std::signbit(a.vertices[i].x), std::signbit(b.vertices[i].x)) << i;
  }
  EXPECT_EQ(a.vertex_markers, (std::vector<int>{1, 0, 1, 0}));
  EXPECT_EQ(b.vertex_markers, a.vertex_markers);
  EXPECT_EQ(a.vertex_lines, (std::vector<int>{2, 3, 4, 5}));
  EXPECT_EQ(b.vertex_lines, (std::vector<int>{2, 5, 6, 7}));
  EXPECT_EQ(a.vertices[2].y, 1e300);

  // A mesh of those vertices: the triangle number is never read, a 6-node triangle's
  // last three corners neither; the ids plain and otherwise.
  write("p.node", plain);
  write("p.ele", "2 6 1\nfirst 1 2 3 9 9 9 0.5\n2 1 3 4 x y z w\n");
  write("g.node", general);
  write("g.ele", "2 6 1 # header\n1 +1 2 0003 9 9 9 0.5\n\n2 1 3 4 x y z w#end");
  for (int threads : {1, 2}) {
    const Mesh p = read_mesh((dir_ / "p").string(), threads);
    const Mesh g = read_mesh((dir_ / "g").string(), threads);
    EXPECT_EQ(p.triangles, (std::vector<Tri>{{0, 1, 2}, {0, 2, 3}})) << threads;
    EXPECT_EQ(g.triangles, p.triangles) << threads;
  }
}

// The first error and its line after plain lines, each message as the general path
// words it: the plain path takes no line it would read differently.
TEST_F(PlainLines, ErrorsAfterPlainLinesNameTheirLine) {
  const std::string head = "5 2 0 1\n1 0 0 1\n2 1 0 1\n# note\n3 1 1 0\n";
  EXPECT_EQ(node_error(head + "4 1.5x 2 0\n5 0 1 1\n"), ":6: x coordinate '1.5x' is not a number");
  EXPECT_EQ(node_error(head + "4 1 inf 0\n5 0 1 1\n"), ":6: y coordinate 'inf' is not finite (NaN or infinite)");
  EXPECT_EQ(node_error(head + "4 1 1e400 0\n5 0 1 1\n"),
            ":6: y coordinate '1e400' is too large for a double (overflows)");
  EXPECT_EQ(node_error(head + "4x 1 1 0\n5 0 1 1\n"), ":6: vertex number '4x' is not an integer");
  EXPECT_EQ(node_error(head + "4-1 1 0\n5 0 1 1\n"), ":6: vertex number '4-1' is not an integer");
  EXPECT_EQ(node_error(head + "4 1.5-2 0\n5 0 1 1\n"), ":6: x coordinate '1.5-2' is not a number");
  EXPECT_EQ(node_error(head + "5 1 1 0\n5 0 1 1\n"), ":6: vertex number 5 out of order (expected 4)");
  EXPECT_EQ(node_error(head + "5 1.5x 1 0\n5 0 1 1\n"), ":6: vertex number 5 out of order (expected 4)");
  EXPECT_EQ(node_error(head + "4 1 1 0\n5 0 1 99999999999999999999\n"),
            ":7: boundary marker '99999999999999999999' is out of range");
  // Forty digits: the plain path counts them without adding past the 18th (adding
  // overflowed, which the sanitizer build stops at), and the general path names them.
  EXPECT_EQ(node_error(head + "4000000000000000000000000000000000000000 1 1 0\n5 0 1 1\n"),
            ":6: vertex number '4000000000000000000000000000000000000000' is out of range");
  EXPECT_EQ(node_error(head + "4 1 1\n5 0 1 1\n6 0 0 0\n"), ":8: unexpected content after the last vertex");
  EXPECT_EQ(node_error(head + "4 1 1 0\n"), ":6: unexpected end of file: expected vertex 5 of 5");
  // Extra fields: a column on every line is ignored, on one line of five it is an error
  // (the plain lines count among the section's lines).
  EXPECT_EQ(node_error("5 2 0 1\n1 0 0 1\n2 1 0 1\n3 1 1 0\n4 1 1 0 9\n5 0 1 1\n"),
            ":5: vertex line (number, x, y, attributes, marker): expected at most 4 fields, found 5 (extra fields, "
            "on 1 of the section's 5 lines; an extra column on every line would be ignored)");
  EXPECT_EQ(node_error("2 2 0 0\n1 0 0 1\n2 1 0 1\n"), "");
  EXPECT_EQ(node_error("1 2 0 0\n2 0 0\n"), ":2: first vertex is numbered 2; must be 0 or 1");

  const std::string node = "4 2 0 1\n1 0 0 1\n2 1 0 1\n3 1 1 1\n4 0 1 1\n";
  for (int threads : {1, 2}) {
    EXPECT_EQ(mesh_error(node, "3 3 0\n1 1 2 3\n2 1 3 4\n3 1 3 5\n", threads),
              ".ele:4: vertex id 5 out of range (1 to 4)")
        << threads;
    EXPECT_EQ(mesh_error(node, "3 3 0\n1 1 2 3\n2 1 3 4\n3 1 9 z\n", threads),
              ".ele:4: vertex id 9 out of range (1 to 4)")
        << threads;
    EXPECT_EQ(mesh_error(node, "3 3 0\n1 1 2 3\n2 1 3 4\n3 1 z 9\n", threads),
              ".ele:4: vertex id 'z' is not an integer")
        << threads;
    EXPECT_EQ(mesh_error(node, "2 3 0\n1 1 2 3\n2 1 3 9999999999999999999\n", threads),
              ".ele:3: vertex id '9999999999999999999' is out of range")
        << threads;
    EXPECT_EQ(mesh_error(node, "2 3 0\n1 1 2 3\n2 1 3 -999999999999999999\n", threads),
              ".ele:3: vertex id -999999999999999999 out of range (1 to 4)")
        << threads;
    EXPECT_EQ(mesh_error(node, "2 3 0\n1 1 2 3\n2 1 3 4 5\n", threads),
              ".ele:3: triangle line (number, corners, attributes): expected at most 4 fields, found 5 (extra fields)")
        << threads;
    EXPECT_EQ(mesh_error(node, "2 3 0\n1 1 2 3\n2 1 3-4\n", threads),
              ".ele:3: triangle line (number, corners, attributes): expected 4 fields, found 3")
        << threads;
    EXPECT_EQ(mesh_error(node, "2 3 0\n1 1 2 3\n2 1 3\n", threads),
              ".ele:3: triangle line (number, corners, attributes): expected 4 fields, found 3")
        << threads;
    EXPECT_EQ(mesh_error(node, "2 3 1\n1 1 2 3 0.5\n2 1 3 4\n", threads),
              ".ele:3: triangle line (number, corners, attributes): expected 5 fields, found 4")
        << threads;
    EXPECT_EQ(mesh_error(node, "3 3 0\n1 1 2 3\n2 1 3 4\n", threads),
              ".ele:3: unexpected end of file: expected triangle 3 of 3")
        << threads;
    EXPECT_EQ(mesh_error(node, std::string("2 3 0\n1 1 2 3\n2 1 3 4\0\n", 23), threads),
              ".ele:3: vertex id '4\\x00' is not an integer")
        << threads;
  }
}

// A large mesh broken far from the start (the last .node line, the last .ele line, a
// line in the middle, both files): one thread and two give the same first error.
TEST_F(PlainLines, LateErrorsInLargeFilesAreTheSameOnAnyThreadCount) {
  const int n = 3000;  // vertices in a row of quads, 2 (n/2 - 1) triangles
  std::string node = std::to_string(n) + " 2 0 1\n", ele = std::to_string(n - 2) + " 3 0\n";
  for (int i = 0; i < n; ++i) node += std::to_string(i + 1) + " " + std::to_string(i / 2) + ".125 " + std::to_string(i % 2) + " 0\n";
  for (int q = 0; q < n / 2 - 1; ++q) {
    const int a = 2 * q + 1, b = a + 2, c = a + 3, d = a + 1;
    ele += std::to_string(2 * q + 1) + " " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + "\n";
    ele += std::to_string(2 * q + 2) + " " + std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(d) + "\n";
  }
  auto replace_line = [](std::string text, int line, const std::string& with) {
    std::size_t at = 0;
    for (int k = 1; k < line; ++k) at = text.find('\n', at) + 1;
    return text.replace(at, text.find('\n', at) - at, with);
  };
  EXPECT_EQ(mesh_error(node, ele, 1), "");
  const std::string node_last = replace_line(node, n + 1, "3000 1 1 q");
  const std::string node_mid = replace_line(node, 1500, "1499 1e400 0 0");
  const std::string ele_last = replace_line(ele, n - 1, "2998 1 2 3001");
  const std::string ele_mid = replace_line(ele, 1700, "1699 1 2");
  const std::vector<std::tuple<std::string, std::string, std::string>> cases = {
      {node_last, ele, ".node:3001: boundary marker 'q' is not an integer"},
      {node_mid, ele, ".node:1500: x coordinate '1e400' is too large for a double (overflows)"},
      {node, ele_last, ".ele:2999: vertex id 3001 out of range (1 to 3000)"},
      {node, ele_mid, ".ele:1700: triangle line (number, corners, attributes): expected 4 fields, found 3"},
      {node_last, ele_mid, ".node:3001: boundary marker 'q' is not an integer"},
  };
  for (const auto& [n_text, e_text, error] : cases)
    for (int threads : {1, 2, 0}) EXPECT_EQ(mesh_error(n_text, e_text, threads), error) << threads;
}

// A header's count against the lines left, counted 64 bytes at a time and then byte by
// byte: files of every length from 0 to 160 bytes after the header, newlines at varying
// places; the count in the message is the file's newlines after the header, plus one
// (none when nothing follows the header).
TEST_F(PlainLines, LinesLeftCountsEveryNewline) {
  const std::string node = "1 2 0 0\n1 0 0\n";
  for (std::size_t length = 0; length <= 160; ++length) {
    std::string rest;
    for (std::size_t k = 0; k < length; ++k) rest += (k * 7 + length) % 5 == 0 ? '\n' : '#';
    const std::size_t left = rest.empty() ? 0 : 1 + static_cast<std::size_t>(std::count(rest.begin(), rest.end(), '\n'));
    EXPECT_EQ(mesh_error(node, "999 3 0\n" + rest, 1),
              ".ele:1: triangle count is 999 but the file has only " + std::to_string(left) + " more lines")
        << length;
  }
}

}  // namespace
}  // namespace lepp
