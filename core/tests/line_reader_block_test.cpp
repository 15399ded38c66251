// SPDX-License-Identifier: GPL-3.0-or-later
// The reader's fixed buffer (LineReader reads a file a block at a time, issue 40): a number,
// a token, a comment or a line split across two reads reads as it does whole. Each file is
// read with blocks of 1 to 40 bytes and with the default block (which holds these files
// whole, as the reader of the whole text did): the same tokens, values, line numbers,
// counts of lines left and first error, step for step. Then files larger than the default
// block through read_node and read_mesh, and a pipe (read whole, its lines counted).
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "scratch_files.h"

#include "../src/line_reader.h"
#include "lepp/io.h"
#include "lepp/mesh_read.h"

namespace fs = std::filesystem;

namespace lepp {
namespace {

using detail::LineReader;

using LineReaderBlock = ScratchFiles;

// Everything a reader with `block` bytes of buffer gives for the file, step by step: the
// lines left before each step, then a plain 4-field line ("irri") where one is, else the
// next line's tokens (each converted as an integer and as a real, their messages kept);
// the error that ends the file, if any.
std::string transcript(const std::string& path, std::size_t block) {
  std::string out;
  try {
    LineReader in(path, block);
    std::vector<std::string_view> tokens;
    std::int64_t ints[2];
    double reals[2];
    for (int step = 0; step < 1000; ++step) {
      out += fmt::format("left {}; ", in.lines_left());
      if (in.plain("irri", ints, reals)) {
        out += fmt::format("plain:{} {} {:.17g} {:.17g} {}\n", in.line(), ints[0], reals[0], reals[1], ints[1]);
        continue;
      }
      if (!in.next(tokens)) break;
      out += fmt::format("line {}:", in.line());
      for (std::string_view t : tokens) {
        out += " [" + std::string(t) + "]";
        try {
          out += fmt::format("={}", in.integer(t, "integer"));
        } catch (const InputError& e) {
          out += fmt::format("({})", e.what());
        }
        try {
          out += fmt::format("={:.17g}", in.real(t, "real"));
        } catch (const InputError& e) {
          out += fmt::format("({})", e.what());
        }
      }
      out += "\n";
    }
  } catch (const InputError& e) {
    out += fmt::format("error: {}\n", e.what());
  }
  return out;
}

TEST_F(LineReaderBlock, SplitNumbersAndLinesReadAsWhole) {
  const std::vector<std::string> texts = {
      // comments, blank lines, tabs, a comment at a line's end, plain and general lines,
      // long numbers, no newline at the end
      "# a .node\n5 2 0 1\n1 0.5 1e3 1\n\n   \n2\t-7 123456789.25 0 # note\n3 1.0000000000000002 2 1\n"
      "4 0x1p3 2 1\n5 -12345678901234567 0.1 1",
      // a line longer than every small block, a comment longer still, CRLF ends
      "1 2 3 " + std::string(100, '7') + " 9\r\n# " + std::string(150, 'c') + "\r\n" + "2 0.25 0.5 0\r\n",
      // NUL inside a line and at a line's start, a '#' right after a number
      std::string("1 2\0x 3\n\0 4\n7 1.5 2.5 8#c\n8 1 2 3\n", 31),
      // empty lines only, a file of one newline, the last line a lone number
      "\n\n\n", "\n", "42",
  };
  for (const std::string& text : texts) {
    const std::string path = write("t.txt", text);
    const std::string whole = transcript(path, LineReader::kBlock);
    for (std::size_t block = 1; block <= 40; ++block) EXPECT_EQ(transcript(path, block), whole) << block << ": " << text;
  }
  // What the whole read gives, to know the comparison is not of two empty transcripts.
  const std::string first = transcript(write("t.txt", texts[0]), 3);
  EXPECT_NE(first.find("line 6: [2]=2=2 [-7]=-7=-7 [123456789.25]"), std::string::npos) << first;
  EXPECT_NE(first.find("plain:3 1 0.5 1000 1"), std::string::npos) << first;
  EXPECT_NE(first.find("left 1; plain:9 5 -12345678901234568 0.10000000000000001 1"), std::string::npos) << first;
  EXPECT_NE(first.find("left 7; plain:3 1 0.5 1000 1"), std::string::npos) << first;
}

// The numbers split at every place: each line's value as the reader of the whole text reads it.
TEST_F(LineReaderBlock, NumberSplitAtEveryByte) {
  const std::string text = "1 123456789012345678 -0.000123456789012345678e-300 1\n";
  const std::string path = write("n.txt", text + text);
  for (std::size_t block = 1; block <= text.size() + 2; ++block) {
    LineReader in(path, block);
    std::int64_t ints[2];
    double reals[2];
    for (int line = 1; line <= 2; ++line) {
      ASSERT_TRUE(in.plain("irri", ints, reals)) << block;
      EXPECT_EQ(in.line(), line);
      EXPECT_EQ(reals[0], 123456789012345678.0) << block;
      EXPECT_EQ(reals[1], -0.000123456789012345678e-300) << block;
    }
    std::vector<std::string_view> tokens;
    EXPECT_FALSE(in.next(tokens));
    EXPECT_EQ(in.lines_left(), 0u);
  }
}

// Files larger than the default block, through the readers the certifier uses: the same
// mesh, and an error on the last line named at its line.
TEST_F(LineReaderBlock, LargeFilesReadPastManyBlocks) {
  const int n = 40000;  // about 0.8 MB of .node: a few blocks
  std::string node = std::to_string(n) + " 2 0 1\n# comment\n", ele = std::to_string(n - 2) + " 3 0\n";
  for (int i = 0; i < n; ++i)
    node += fmt::format("{} {}.{} {}.0625 0\n", i + 1, i / 2, std::string(8, static_cast<char>('1' + i % 9)), i % 2);
  for (int q = 0; q < n / 2 - 1; ++q) {
    const int a = 2 * q + 1, b = a + 2, c = a + 3, d = a + 1;
    ele += fmt::format("{} {} {} {}\n{} {} {} {}\n", 2 * q + 1, a, b, c, 2 * q + 2, a, c, d);
  }
  ASSERT_GT(node.size(), 3 * LineReader::kBlock);
  write("m.node", node);
  write("m.ele", ele);
  const std::string prefix = (dir_ / "m").string();
  for (int threads : {1, 2}) {
    const Mesh mesh = read_mesh(prefix, threads);
    ASSERT_EQ(mesh.vertices.size(), static_cast<std::size_t>(n));
    ASSERT_EQ(mesh.triangles.size(), static_cast<std::size_t>(n - 2));
    EXPECT_EQ(mesh.vertices[n - 1].x, 19999.44444444);
    EXPECT_EQ(mesh.vertices[n - 1].y, 1.0625);
    EXPECT_EQ(mesh.triangles[n - 3], (Tri{n - 4, n - 1, n - 3}));
  }
  write("m.ele", ele.substr(0, ele.size() - 2) + "x\n");
  try {
    read_mesh(prefix, 1);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), prefix + ".ele:" + std::to_string(n - 1) + ": vertex id '3999x' is not an integer");
  }
  // A header promising one line more than the file holds (n - 2 lines and the empty one
  // after the last newline), found only past its last block.
  write("m.ele", std::to_string(n) + ele.substr(ele.find(' ')));
  try {
    read_mesh(prefix, 1);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), prefix + ".ele:1: triangle count is " + std::to_string(n) +
                                         " but the file has only " + std::to_string(n - 1) + " more lines");
  }
}

// A header's count larger than the lines left, checked only when reading fails
// (LineReader::count_later): the header's error whatever comes first after it, as when the
// count was checked at the header; a count that is right keeps the error of the line.
TEST_F(LineReaderBlock, CountsCheckedLateReportTheHeader) {
  const std::string node = "4 2 0 0\n1 0 0\n2 1 0\n3 0 1\n4 1 1\n";
  const std::string prefix = (dir_ / "m").string();
  auto mesh_error = [&](const std::string& n, const std::string& e) {
    write("m.node", n);
    write("m.ele", e);
    std::string errors[2];
    for (int threads : {1, 2})
      try {
        read_mesh(prefix, threads);
      } catch (const InputError& error) {
        errors[threads - 1] = std::string(error.what()).substr(prefix.size());
      }
    EXPECT_EQ(errors[0], errors[1]);  // the same on any thread count
    return errors[0];
  };
  const std::string tri = "1 1 2 3\n2 2 4 3\n";
  // 3 promised, 2 lines and the empty one after the last newline: 3 lines, no error at the
  // header; the end of the file is the error.
  EXPECT_EQ(mesh_error(node, "3 3 0\n" + tri), ".ele:3: unexpected end of file: expected triangle 3 of 3");
  // 4 promised, 3 lines: the header's error, not the end of the file's, nor a bad line's.
  EXPECT_EQ(mesh_error(node, "4 3 0\n" + tri), ".ele:1: triangle count is 4 but the file has only 3 more lines");
  EXPECT_EQ(mesh_error(node, "4 3 0\n1 1 2 3\n2 2 4 9\n"), ".ele:1: triangle count is 4 but the file has only 3 more lines");
  EXPECT_EQ(mesh_error(node, "4 3 0\n1 1 2 x\n2 2 4 3\n"), ".ele:1: triangle count is 4 but the file has only 3 more lines");
  EXPECT_EQ(mesh_error(node, "4 4 0\n" + tri), ".ele:1: triangle count is 4 but the file has only 3 more lines");  // the header's next field
  // A blank line right after the header is one of the lines left.
  EXPECT_EQ(mesh_error(node, "4 3 0\n\n" + tri), ".ele:4: unexpected end of file: expected triangle 3 of 4");
  EXPECT_EQ(mesh_error(node, "5 3 0\n\n" + tri), ".ele:1: triangle count is 5 but the file has only 4 more lines");
  // Right counts: the line's own error.
  EXPECT_EQ(mesh_error(node, "2 3 0\n1 1 2 3\n2 2 4 9\n"), ".ele:3: vertex id 9 out of range (1 to 4)");
  EXPECT_EQ(mesh_error(node, "2 4 0\n" + tri), ".ele:1: nodes per triangle must be 3 or 6");
  EXPECT_EQ(mesh_error(node, "-1 3 0\n" + tri), ".ele:1: triangle count is -1 but the file has only 3 more lines");
  EXPECT_EQ(mesh_error(node, "2 3 0\n" + tri), "");
  // The .node: its vertex count, and then the .ele is not read.
  EXPECT_EQ(mesh_error("6 2 0 0\n1 0 0\n2 1 0\n3 0 1\n4 1 1\n", "2 3 0\n" + tri),
            ".node:1: vertex count is 6 but the file has only 5 more lines");
  EXPECT_EQ(mesh_error("6 2 0 0\n1 0 0\n2 1 0\n3 0 1\n5 1 1\n", "2 3 0\n" + tri),
            ".node:1: vertex count is 6 but the file has only 5 more lines");
  EXPECT_EQ(mesh_error("6 3 0 0\n1 0 0\n2 1 0\n3 0 1\n5 1 1\n", "2 3 0\n" + tri),
            ".node:1: vertex count is 6 but the file has only 5 more lines");
  EXPECT_EQ(mesh_error("4 2 0 0\n1 0 0\n2 1 0\n3 0 1\n5 1 1\n", "2 3 0\n" + tri),
            ".node:5: vertex number 5 out of order (expected 4)");
  EXPECT_EQ(mesh_error("-4 2 0 0\n1 0 0\n", "2 3 0\n" + tri), ".node:1: vertex count is negative (-4)");
}

// A pipe cannot be read twice: it is read whole, and its lines counted there.
TEST_F(LineReaderBlock, PipeIsReadWhole) {
  const std::string fifo = (dir_ / "p.node").string();
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  for (const auto& [text, error] : std::vector<std::pair<std::string, std::string>>{
           {"3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n", ""},
           {"5 2 0 0\n1 0 0\n2 1 0\n3 0 1\n", ":1: vertex count is 5 but the file has only 4 more lines"}}) {
    std::thread writer([&, text = text] { std::ofstream(fifo, std::ios::binary) << text; });
    std::string got;
    try {
      const Pslg p = read_node(fifo);
      EXPECT_EQ(p.vertices.size(), 3u);
    } catch (const InputError& e) {
      got = std::string(e.what()).substr(fifo.size());
    }
    writer.join();
    EXPECT_EQ(got, error);
  }
}

}  // namespace
}  // namespace lepp
