// SPDX-License-Identifier: GPL-3.0-or-later
// One long-lived node process runs many Triangle cases (others::TriangleServer,
// `node triangle.js --serve`): the same files and points as one process per
// case, one process started for all of them, a case past its timeout killed and
// the next one served by a new process. Skipped where node or triangle-wasm is
// not installed (scripts/install-deps.sh installs both).
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include <gtest/gtest.h>

#include "../loop/audit_test_support.h"
#include "lepp/engines/peer_engines.h"
#include "lepp/io.h"
#include "lepp/validate.h"
#include "triangle_wasm.h"

namespace fs = std::filesystem;
using namespace lepp;
using lepp::audit::test::slurp;

namespace {

const std::string kRoot = LEPP_SOURCE_DIR;

std::string fmt_name(const char* name, double theta, const char* how) {
  return std::string(name) + "-" + std::to_string(static_cast<int>(theta)) + "-" + how;
}

TEST(TriangleServer, SameOutputAsOneProcessPerCase) {
  if (!others::triangle_available(kRoot)) GTEST_SKIP() << "node or triangle-wasm not installed";
  const fs::path dir = fs::temp_directory_path() / ("lepp-triangle-server-" + std::to_string(getpid()));
  fs::create_directories(dir);
  others::TriangleServer server(kRoot);
  int n = 0;
  for (const char* name : {"A", "square400", "rect162", "circles240"})
    for (double theta : {25.0, 30.0}) {
      const std::string poly = kRoot + "/corpus/paper/" + name + ".poly";
      const std::string one = (dir / fmt_name(name, theta, "one")).string(), many = (dir / fmt_name(name, theta, "many")).string();
      const others::TriangleRun a = others::run_triangle(kRoot, poly, theta, 20000, one);
      const others::TriangleRun b = server.run(poly, theta, 20000, many, 60);
      ASSERT_EQ(a.status, 0) << a.output;
      ASSERT_EQ(b.status, 0) << b.output;
      EXPECT_EQ(a.points_added, b.points_added) << name << " " << theta;
      EXPECT_EQ(slurp(one + ".ele"), slurp(many + ".ele")) << name << " " << theta;
      EXPECT_EQ(slurp(one + ".node"), slurp(many + ".node")) << name << " " << theta;
      ++n;
    }
  EXPECT_EQ(server.starts(), 1u) << "one node process for " << n << " cases";
  // A bad input is an answer, not the end of the server.
  const others::TriangleRun bad = server.run((dir / "no-such.poly").string(), 30, 0, (dir / "bad").string(), 60);
  EXPECT_EQ(bad.status, 2) << bad.output;
  EXPECT_EQ(server.starts(), 1u);
  // Past its timeout the case is killed with its process; the next case gets a new one.
  // The case must outlast its timeout on any machine: a paper problem takes
  // about a millisecond in the server, as long as the shortest wait, and a fast
  // machine answered in time (CI, 2026-12-02). 60,000 points take Triangle a
  // few hundred milliseconds, a hundred times the timeout.
  const std::string big = (dir / "big.poly").string();
  {
    std::ofstream out(big);
    std::mt19937_64 rng(20261202);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int points = 60000;
    out.precision(17);
    out << points << " 2 0 0\n";
    for (int i = 1; i <= points; ++i) out << i << " " << u(rng) << " " << u(rng) << "\n";
    out << "0 0\n0\n";
  }
  const others::TriangleRun late = server.run(big, 30, 0, (dir / "late").string(), 1e-3);
  EXPECT_EQ(late.status, -1);
  EXPECT_NE(late.output.find("killed after"), std::string::npos) << late.output;
  const others::TriangleRun again = server.run(kRoot + "/corpus/paper/A.poly", 30, 20000, (dir / "again").string(), 60);
  EXPECT_EQ(again.status, 0) << again.output;
  EXPECT_EQ(server.starts(), 2u);
  fs::remove_all(dir);
}

TEST(TriangleServer, AuditEngineReadsTheMesh) {
  if (!others::triangle_available(kRoot)) GTEST_SKIP() << "node or triangle-wasm not installed";
  const fs::path dir = fs::temp_directory_path() / ("lepp-triangle-engine-" + std::to_string(getpid()));
  audit::Engine triangle = audit::triangle_engine(kRoot);
  std::vector<std::string> warnings;
  const Pslg a = validate(read_poly(kRoot + "/corpus/paper/A.poly"), warnings);
  for (int i = 0; i < 3; ++i) {
    audit::EngineRequest r;
    r.theta = 30;
    r.work_dir = (dir / std::to_string(i)).string();
    fs::create_directories(r.work_dir);
    const audit::EngineRun run = triangle(a, r);
    ASSERT_EQ(run.status, audit::RunStatus::Ok) << run.detail;
    EXPECT_GT(run.mesh.vertices.size(), a.vertices.size());
  }
  fs::remove_all(dir);
}

}  // namespace
