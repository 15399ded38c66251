// SPDX-License-Identifier: GPL-3.0-or-later
// The `lepp refine` command's answers: exit 2 and one line naming file and
// line for every file in corpus/bad/; exit 3 with the mesh still written (a
// certified CDT) for each loop guard and for unimprovable triangles.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include <nlohmann/json.hpp>

#include "lepp/io.h"
#include "lepp/validate.h"
#ifdef LEPP_HAVE_CERTIFY
#include "lepp/certify.h"
#endif

namespace lepp {
namespace {

namespace fs = std::filesystem;
const std::string kSource = LEPP_SOURCE_DIR;

struct CliRun {
  int status = -1;
  std::string out, err;
};

std::string slurp(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path scratch() {
  fs::path dir = fs::temp_directory_path() / ("lepp_cli_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

// Runs `lepp refine ARGS` (arguments are trusted test strings, no quoting needed).
CliRun refine(const std::string& args) {
  const fs::path dir = scratch();
  const std::string cmd = std::string(LEPP_CLI) + " refine " + args + " > " + (dir / "out").string() + " 2> " +
                          (dir / "err").string();
  int raw = std::system(cmd.c_str());
  CliRun r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  r.out = slurp(dir / "out");
  r.err = slurp(dir / "err");
  return r;
}

bool engine_missing(const CliRun& r) { return r.status == 1 && r.err.find("not implemented") != std::string::npos; }

std::vector<std::string> bad_files() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(kSource + "/corpus/bad"))
    if (entry.path().extension() == ".poly") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

class BadInputCli : public testing::TestWithParam<std::string> {};

TEST_P(BadInputCli, ExitTwoWithOneLineNamingTheFile) {
  const std::string path = kSource + "/corpus/bad/" + GetParam() + ".poly";
  const std::string prefix = (scratch() / "bad").string();
  CliRun r = refine(path + " -o " + prefix + " -q");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
  EXPECT_EQ(r.err.rfind("lepp refine: " + path, 0), 0u) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_FALSE(fs::exists(prefix + ".ele")) << "no mesh for bad input";
}

INSTANTIATE_TEST_SUITE_P(CorpusBad, BadInputCli, testing::ValuesIn(bad_files()),
                         [](const testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

// A guard or unimprovable run: exit 3, the outcome named in the JSON, and the
// written mesh read back and certified as a CDT of the domain (plus the angle
// bound with the unimprovable list when refinement finished).
void expect_stopped_and_certified(const std::string& input, const std::string& options, const char* outcome) {
  const std::string prefix = (scratch() / outcome).string();
  for (const char* ext : {".node", ".ele", ".poly", ".unimprovable"}) fs::remove(prefix + ext);
  CliRun r = refine(input + " -o " + prefix + " --json -q " + options);
  if (engine_missing(r)) GTEST_SKIP() << r.err;
  ASSERT_EQ(r.status, 3) << r.err << r.out;
  nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("outcome"), outcome) << r.out;
  if (std::string(outcome) != "unimprovable") EXPECT_FALSE(j.at("stuck").get<std::string>().empty()) << "which triangle";
  std::vector<std::string> warnings;
  Pslg pslg = validate(read_poly(input), warnings);
  Mesh mesh = read_mesh(prefix);
  EXPECT_FALSE(mesh.triangles.empty());
#ifdef LEPP_HAVE_CERTIFY
  certify::Options co;
  co.unimprovable = read_unimprovable(prefix);
  if (std::string(outcome) == "unimprovable") {
    co.min_angle_deg = j.at("min_angle_target").get<double>();
    EXPECT_FALSE(co.unimprovable.empty()) << "PREFIX.unimprovable lists them";
  }
  certify::Report report = certify::certify(pslg, mesh, co);
  EXPECT_TRUE(report.certified()) << certify::format_report(report);
#endif
}

const std::string kSquare400 = kSource + "/corpus/paper/square400.poly";

TEST(GuardCli, SteinerBudget) { expect_stopped_and_certified(kSquare400, "--min-angle 30 --max-steiner 25", "steiner-budget"); }

TEST(GuardCli, TimeLimit) {
  // A microsecond has passed by the first check of any run that has work to do.
  expect_stopped_and_certified(kSquare400, "--min-angle 33 --time-limit 0.000001", "time-limit");
}

TEST(GuardCli, EdgeFloor) {
  // Tips 1e-12 apart: refinement there needs edges far below a floor of 1e-9.
  expect_stopped_and_certified(kSource + "/corpus/hostile/near-touching.poly", "--min-angle 30 --edge-floor 1e-9", "edge-floor");
}

TEST(GuardCli, DefaultEdgeFloorFollowsTheSmallestFeature) {
  // The same input converges with the default floor: 2^-20 x the 1e-12 between the
  // tips, not 2^-20 x the shortest segment (0.2), which stopped it at 20 to 30 degrees.
  const std::string prefix = (scratch() / "near-touching").string();
  CliRun r = refine(kSource + "/corpus/hostile/near-touching.poly -o " + prefix + " -q --min-angle 30");
  if (engine_missing(r)) GTEST_SKIP() << r.err;
  EXPECT_EQ(r.status, 0) << r.err;
}

TEST(GuardCli, Unimprovable) {
  expect_stopped_and_certified(kSource + "/corpus/hostile/small-input-angle.poly", "--min-angle 30", "unimprovable");
}

TEST(GuardCli, ConvergedIsExitZeroAndWarningsGoToStderr) {
  const std::string prefix = (scratch() / "ok").string();
  CliRun r = refine(kSource + "/corpus/hostile/duplicate-vertices.poly -o " + prefix + " -q --min-angle 25");
  if (engine_missing(r)) GTEST_SKIP() << r.err;
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("warning: "), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("converged"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(prefix + ".node") && fs::exists(prefix + ".ele") && fs::exists(prefix + ".poly"));
}

// --json's seconds_by_phase: each phase of the process, for both engines; the engine's
// two (cdt, refine) make up its "seconds". A phase left at zero or missing (a timer
// that no longer wraps its work) fails.
TEST(RefineJsonCli, SecondsByPhase) {
  for (const char* engine : {"fast", "reference"}) {
    const std::string prefix = (scratch() / (std::string("phases-") + engine)).string();
    CliRun r = refine(kSquare400 + " -o " + prefix + " --json -q --min-angle 28 --engine " + engine);
    if (engine_missing(r)) GTEST_SKIP() << r.err;
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    const nlohmann::json& p = j.at("seconds_by_phase");
    EXPECT_EQ(p.size(), 5u) << p.dump();
    for (const char* phase : {"read", "cdt", "refine", "write", "statistics"})
      EXPECT_GT(p.at(phase).get<double>(), 0.0) << engine << " " << phase << ": " << p.dump();
    EXPECT_NEAR(p.at("cdt").get<double>() + p.at("refine").get<double>(), j.at("seconds").get<double>(), 1e-9)
        << engine << ": " << r.out;
  }
}

// --threads 2 writes the statistics beside the files and the .node beside the .ele:
// the same files and the same printed statistics as one thread (the timings aside).
TEST(RefineJsonCli, OutputThreadsWriteTheSameFilesAndStatistics) {
  std::string files[2], text[2];
  for (int threads : {1, 2}) {
    const std::string prefix = (scratch() / ("output-threads-" + std::to_string(threads))).string();
    CliRun r = refine(kSquare400 + " -o " + prefix + " -q --min-angle 30 --max-area 0.5 --threads " + std::to_string(threads));
    if (engine_missing(r)) GTEST_SKIP() << r.err;
    ASSERT_EQ(r.status, 0) << r.err;
    for (const char* ext : {".node", ".ele", ".poly"}) {
      std::ifstream in(prefix + ext, std::ios::binary);
      files[threads - 1] += std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    std::istringstream lines(r.out);
    for (std::string line; std::getline(lines, line);)
      if (line.rfind("seconds", 0) != 0) text[threads - 1] += line + "\n";
  }
  EXPECT_GT(files[0].size(), 10000u);
  EXPECT_TRUE(files[0] == files[1]) << "the files differ";
  EXPECT_NE(text[0].find("smallest angle"), std::string::npos) << text[0];
  EXPECT_EQ(text[0], text[1]);
}

}  // namespace
}  // namespace lepp
