// SPDX-License-Identifier: GPL-3.0-or-later
// The findings' shrunk counterexamples (corpus/theorems/*.txt) still violate the
// statement as written: each file names its statement and holds one input,
// `triangle x y x y x y`, `quad Ax Ay Bx By Cx Cy Dx Dy` or `mesh x y x y ...`.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "lepp/theorems/checks.h"
#include "lepp/theorems/statements.h"

using namespace lepp::theorems;

namespace {

struct CorpusInput {
  std::string statement, kind;
  std::vector<std::int64_t> numbers;
};

CorpusInput read_corpus(const std::filesystem::path& file) {
  std::ifstream in(file);
  CorpusInput c;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("# statement: ", 0) == 0) c.statement = line.substr(13);
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ss(line);
    ss >> c.kind;
    for (std::int64_t v; ss >> v;) c.numbers.push_back(v);
  }
  return c;
}

std::vector<GridPoint> points(const std::vector<std::int64_t>& n) {
  std::vector<GridPoint> p;
  for (std::size_t i = 0; i + 1 < n.size(); i += 2) p.push_back({n[i], n[i + 1]});
  return p;
}

// The statement's check on one corpus input: the verdict that must violate it.
Verdict check_corpus(const CorpusInput& c) {
  auto p = points(c.numbers);
  using Quad = std::function<Verdict(const TerminalQuad&)>;
  using Mesh = std::function<Verdict(const TerminalInMesh&)>;
  static const std::map<std::string, Quad> quads = {
      {"Corollary12.CentroidInsideBetterTriangle", check_corollary12},
      {"Lemma11.CentroidBoundsInLongestEdgeCoordinates", check_lemma11},
      {"Remark13.CentroidDistanceAtLeast075ShortestEdge", check_remark13},
      {"Theorem14.CentroidNotCollinearExceptRightIsosceles", check_theorem14},
  };
  static const std::map<std::string, Mesh> meshes = {
      {"Proposition6.MidpointNearestVertexInDelaunayMesh", check_prop6a_mesh},
      {"Lemma8.AcuteBelowAlphaLimitDistanceAbove13", [](const TerminalInMesh& m) { return check_lemma8(m, Lemma8Part::a_i); }},
      {"Lemma8.AcuteBelow30DistanceAbove096", [](const TerminalInMesh& m) { return check_lemma8(m, Lemma8Part::a_ii); }},
  };
  if (c.kind == "triangle" && c.statement == "Lemma4.BisectionImprovesTBLeavesObtuseTA")
    return check_lemma4(GridTriangle{{p.at(0), p.at(1), p.at(2)}});
  if (c.kind == "quad") return quads.at(c.statement)(TerminalQuad{p.at(0), p.at(1), p.at(2), p.at(3)});
  if (c.kind == "mesh") {
    // The mesh violates the statement when one of its terminal pairs does.
    Verdict all;
    all.hypothesis = false;
    for (const auto& pair : delaunay_terminal_pairs(p)) {
      Verdict v = meshes.at(c.statement)(pair);
      if (v.hypothesis && !v.conclusion) return v;
    }
    all.detail = "no terminal pair of the mesh violates the statement";
    return all;
  }
  throw std::runtime_error("unknown corpus input " + c.kind + " for " + c.statement);
}

}  // namespace

TEST(TheoremsCorpus, EveryFindingsCounterexampleStillViolatesItsStatement) {
  const std::filesystem::path dir = std::filesystem::path(LEPP_SOURCE_DIR) / "corpus" / "theorems";
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".txt") continue;
    ++files;
    CorpusInput c = read_corpus(entry.path());
    SCOPED_TRACE(entry.path().filename().string() + " (" + c.statement + ")");
    const Statement* s = find_statement(c.statement);
    ASSERT_NE(s, nullptr) << "the corpus file names no statement of the registry";
    EXPECT_FALSE(s->finding.empty()) << "a counterexample for a statement not marked as a finding";
    Verdict v = check_corpus(c);
    EXPECT_TRUE(v.hypothesis) << v.detail;
    EXPECT_FALSE(v.conclusion) << v.detail;
    // The narrowed statement accepts it or excludes it by its hypothesis.
    EXPECT_FALSE(s->narrowed.empty());
  }
  EXPECT_GE(files, 7);
}

// Every finding names a corpus file that exists and a narrowed row of the registry.
TEST(TheoremsCorpus, EveryFindingIsDocumented) {
  for (const auto& s : statements()) {
    if (s.finding.empty()) continue;
    SCOPED_TRACE(s.suite + "." + s.name);
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(LEPP_SOURCE_DIR) / s.corpus));
    const Statement* n = find_statement(s.narrowed);
    ASSERT_NE(n, nullptr);
    EXPECT_TRUE(n->finding.empty()) << "the narrowed statement is itself a finding";
  }
}
