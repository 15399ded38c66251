// SPDX-License-Identifier: GPL-3.0-or-later
// read_mesh(prefix, threads) (lepp/mesh_read.h): the .node and the .ele read at once give
// the mesh the sequential read gives, and on broken files the same first error, with its
// file and line: the .node's before the .ele's, an out-of-range corner before a later
// syntax error, a corner too large for an int, the .poly's own.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "lepp/io.h"
#include "lepp/mesh_read.h"

namespace lepp {
namespace {

struct Files {
  std::string node, ele, poly;  // poly empty: no .poly
};

std::string write(const std::string& name, const Files& f) {
  const std::string prefix = (std::filesystem::temp_directory_path() / ("lepp_mesh_read_threads_" + name + "_" + std::to_string(::getpid()))).string();
  for (const char* ext : {".node", ".ele", ".poly"}) std::filesystem::remove(prefix + ext);
  std::ofstream(prefix + ".node") << f.node;
  std::ofstream(prefix + ".ele") << f.ele;
  if (!f.poly.empty()) std::ofstream(prefix + ".poly") << f.poly;
  return prefix;
}

// What a read gives: the mesh as text, or the error's file, line and message.
std::string outcome(const std::string& prefix, int threads) {
  try {
    const Mesh m = read_mesh(prefix, threads);
    std::string s;
    for (const Point& p : m.vertices) s += std::to_string(p.x) + "," + std::to_string(p.y) + " ";
    for (const Tri& t : m.triangles) s += std::to_string(t[0]) + "-" + std::to_string(t[1]) + "-" + std::to_string(t[2]) + " ";
    for (const ConstrainedEdge& e : m.constrained_edges) s += std::to_string(e.a) + "=" + std::to_string(e.b) + " ";
    return s;
  } catch (const InputError& e) {
    return std::string("error: ") + e.what() + " @" + std::to_string(e.line());
  }
}

const std::string kNode1 = "4 2 0 1\n1 0 0 1\n2 1 0 1\n3 1 1 1\n4 0 1 1\n";
const std::string kNode0 = "4 2 0 1\n0 0 0 1\n1 1 0 1\n2 1 1 1\n3 0 1 1\n";
const std::string kEle1 = "2 3 0\n1 1 2 3\n2 1 3 4\n";
const std::string kEle0 = "2 3 0\n0 0 1 2\n1 0 2 3\n";
const std::string kPoly1 = "0 2 0 1\n2 1\n1 1 2 1\n2 3 4 1\n";

TEST(MeshReadThreads, SameMeshAsTheSequentialRead) {
  for (const auto& [name, files] : std::vector<std::pair<std::string, Files>>{
           {"one_based", {kNode1, kEle1, kPoly1}}, {"zero_based", {kNode0, kEle0, ""}}, {"no_poly", {kNode1, kEle1, ""}}}) {
    const std::string prefix = write(name, files);
    const std::string one = outcome(prefix, 1);
    ASSERT_EQ(one.rfind("error", 0), std::string::npos) << name << ": " << one;
    EXPECT_EQ(outcome(prefix, 2), one) << name;
    EXPECT_EQ(outcome(prefix, 0), one) << name;
  }
  // The 1-based files give 0-based ids: the deferred ids are shifted.
  EXPECT_EQ(outcome(write("shift", {kNode1, kEle1, kPoly1}), 2).substr(outcome(write("shift", {kNode1, kEle1, kPoly1}), 2).find("0-1-2")),
            "0-1-2 0-2-3 0=1 2=3 ");
}

TEST(MeshReadThreads, SameFirstErrorOnBrokenFiles) {
  const std::vector<std::pair<std::string, Files>> cases = {
      {"node_broken", {"4 2 0 1\n1 0 0 1\n2 x 0 1\n3 1 1 1\n4 0 1 1\n", kEle1, ""}},
      // A mesh keeps no markers, but a marker that is no integer is still an error.
      {"node_marker_broken", {"4 2 0 1\n1 0 0 1\n2 1 0 m\n3 1 1 1\n4 0 1 1\n", kEle1, ""}},
      {"both_broken", {"4 2 0 1\n1 0 0 1\n2 x 0 1\n3 1 1 1\n4 0 1 1\n", "2 3 0\n1 1 2 3\n2 1 3 y\n", ""}},
      {"corner_out_of_range", {kNode1, "2 3 0\n1 1 2 5\n2 1 3 4\n", ""}},
      {"corner_zero_when_one_based", {kNode1, "2 3 0\n1 0 2 3\n2 1 3 4\n", ""}},
      {"out_of_range_before_syntax", {kNode1, "2 3 0\n1 1 2 9\n2 1 3 z\n", ""}},
      {"corner_beyond_int", {kNode1, "2 3 0\n1 1 2 4294967298\n2 1 3 4\n", ""}},
      {"ele_short", {kNode1, "3 3 0\n1 1 2 3\n2 1 3 4\n", ""}},
      {"ele_missing", {kNode1, "", ""}},
      {"poly_out_of_range", {kNode1, kEle1, "0 2 0 1\n1 1\n1 1 7 1\n"}},
      {"poly_syntax", {kNode1, kEle1, "0 2 0 1\n1 1\n1 1 q 1\n"}},
      {"poly_and_ele_broken", {kNode1, "2 3 0\n1 1 2 3\n2 1 3 y\n", "0 2 0 1\n1 1\n1 1 q 1\n"}},
  };
  for (const auto& [name, files] : cases) {
    const std::string prefix = write(name, files);
    if (name == "ele_missing") std::filesystem::remove(prefix + ".ele");
    const std::string one = outcome(prefix, 1);
    ASSERT_EQ(one.rfind("error", 0), 0u) << name << " is read without error: " << one;
    EXPECT_EQ(outcome(prefix, 2), one) << name;
  }
}

}  // namespace
}  // namespace lepp
