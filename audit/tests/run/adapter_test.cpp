// SPDX-License-Identifier: GPL-3.0-or-later
// The command adapter against programs that misbehave (tiny shell scripts in
// programs/): every way a program can fail becomes a RunStatus, none crashes or
// hangs the audit; bad templates are usage errors.
#include <signal.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "lepp/audit/judge/checks.h"
#include "lepp/engines/command_engine.h"
#include "lepp/audit/run/subprocess.h"
#include "lepp/io.h"
#include "lepp/validate.h"

#include "validated_square.h"

namespace fs = std::filesystem;
using namespace lepp;
using namespace lepp::audit;

namespace {

const std::string kPrograms = LEPP_AUDIT_PROGRAMS;

Pslg square() { return audit_test::validated_square(); }

struct Scratch {
  fs::path dir;
  Scratch() {
    std::string t = (fs::temp_directory_path() / "lepp-adapter-XXXXXX").string();
    dir = mkdtemp(t.data());
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

EngineRun run(const std::string& templ, double timeout = 5) {
  Scratch s;
  EngineRequest r;
  r.theta = 25;
  r.timeout_seconds = timeout;
  r.work_dir = s.dir.string();
  return command_engine(templ)(square(), r);
}

TEST(CommandAdapter, GarbageOutputIsUnreadable) {
  EngineRun r = run(kPrograms + "/garbage.sh {in} {out}");
  EXPECT_EQ(r.status, RunStatus::UnreadableOutput) << r.detail;
  EXPECT_FALSE(r.detail.empty());
}

TEST(CommandAdapter, MissingOutputIsUnreadable) {
  EngineRun r = run(kPrograms + "/missing.sh {in} {out}");
  EXPECT_EQ(r.status, RunStatus::UnreadableOutput);
  EXPECT_NE(r.detail.find("out.node"), std::string::npos) << r.detail;
}

TEST(CommandAdapter, NonZeroExitKeepsStatusAndStderr) {
  EngineRun r = run(kPrograms + "/exit3.sh {in} {out}");
  EXPECT_EQ(r.status, RunStatus::ExitCode);
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.stderr_text.find("cannot mesh"), std::string::npos);
}

TEST(CommandAdapter, HangIsKilledAtTheTimeout) {
  // The script never ends and its child ignores SIGTERM: returning at all (ctest's
  // timeout would catch a hang) with TimedOut shows the whole group was killed.
  EngineRun r = run(kPrograms + "/hang.sh {in} {out}", 0.5);
  EXPECT_EQ(r.status, RunStatus::TimedOut);
  CaseResult c = check_run(square(), EngineRequest{Method::Centroid, 25, 0.5, 0, ""}, r, {});
  EXPECT_EQ(c[Row::Termination].verdict, Verdict::Failed);
  CaseResult above = check_run(square(), EngineRequest{Method::Centroid, 33, 0.5, 0, ""}, r, {});
  EXPECT_EQ(above[Row::Termination].verdict, Verdict::Finding);
}

TEST(CommandAdapter, CrashIsASignal) {
  EngineRun r = run(kPrograms + "/crash.sh {in} {out}");
  EXPECT_EQ(r.status, RunStatus::Crashed);
  EXPECT_EQ(r.signal, SIGSEGV) << r.detail;
  CaseResult c = check_run(square(), EngineRequest{}, r, {});
  EXPECT_EQ(c[Row::Certificate].verdict, Verdict::Failed);
}

TEST(CommandAdapter, ZeroBasedMeshReads) {
  Scratch s;
  std::ofstream(s.dir / "m.node") << "4 2 0 0\n0 0 0\n1 4 0\n2 4 4\n3 0 4\n";
  std::ofstream(s.dir / "m.ele") << "2 3 0\n0 0 1 2\n1 0 2 3\n";
  EngineRun r = run(kPrograms + "/copy_mesh.sh {in} {out} " + (s.dir / "m").string());
  ASSERT_EQ(r.status, RunStatus::Ok) << r.detail;
  EXPECT_EQ(r.mesh.triangles.size(), 2u);
  CaseResult c = check_run(square(), EngineRequest{Method::Centroid, 25, 5, 0, ""}, r, {});
  EXPECT_EQ(c[Row::Certificate].verdict, Verdict::Held) << c[Row::Certificate].detail;
  EXPECT_EQ(c[Row::MinAngle].verdict, Verdict::Held);
}

TEST(CommandAdapter, ACheckerRejectsAWrongMesh) {
  // One triangle of the square only: the domain is not covered.
  Scratch s;
  std::ofstream(s.dir / "m.node") << "4 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n";
  std::ofstream(s.dir / "m.ele") << "1 3 0\n1 1 2 3\n";
  EngineRun r = run(kPrograms + "/copy_mesh.sh {in} {out} " + (s.dir / "m").string());
  ASSERT_EQ(r.status, RunStatus::Ok) << r.detail;
  CaseResult c = check_run(square(), EngineRequest{}, r, {});
  EXPECT_EQ(c[Row::Certificate].verdict, Verdict::Failed);
}

TEST(CommandTemplate, UnknownPlaceholderIsAUsageError) {
  EXPECT_THROW(check_command_template(kPrograms + "/missing.sh {in} {out} {angle}"), UsageError);
}

TEST(CommandTemplate, ProgramNotFoundIsAUsageError) {
  EXPECT_THROW(check_command_template("/no/such/mesher {in} {out}"), UsageError);
  EXPECT_THROW(check_command_template("no-such-mesher-anywhere {in} {out}"), UsageError);
}

TEST(CommandTemplate, InAndOutAreRequired) { EXPECT_THROW(check_command_template("sh -c true {in}"), UsageError); }

TEST(CommandTemplate, ValuesAreQuotedForTheShell) {
  std::string c = expand_command_template("m {in} {out} {theta} {method}", "a b'c", "/o", 22.5, Method::Midpoint);
  EXPECT_EQ(c, "m 'a b'\\''c' '/o' '22.5' 'midpoint'");
}

TEST(Subprocess, StderrIsCapped) {
  SubprocessLimits l;
  l.stderr_cap = 100;
  SubprocessResult r = run_subprocess("head -c 100000 /dev/zero | tr '\\0' x >&2", l);
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.stderr_text.size(), 100u);
  EXPECT_TRUE(r.stderr_truncated);
}

TEST(Subprocess, MemoryCapApplies) {
  SubprocessLimits l;
  l.memory_mb = 64;
  // A 256 MB allocation under a 64 MB cap fails.
  SubprocessResult r = run_subprocess("python3 -c 'x = bytearray(256 * 1024 * 1024)' 2>/dev/null || exit 9", l);
  EXPECT_EQ(r.exit_code, 9);
}

}  // namespace
