// SPDX-License-Identifier: GPL-3.0-or-later
// The two ways subprocess.h makes a child give the same run: posix_spawn when no memory
// cap is asked (no copy of the parent's page tables), fork when one is (setrlimit in the
// child). Each test runs both: its own process group, stdin and stdout on /dev/null,
// SIGINT, SIGTERM and SIGPIPE at their defaults whatever the parent set, the working
// directory, and the ends of a program that cannot run or a directory it cannot enter.
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lepp/audit/run/subprocess.h"

namespace fs = std::filesystem;
using namespace lepp::audit;

namespace {

// memory_mb 0: posix_spawn; a cap far above what the child uses: fork.
SubprocessLimits limits_for(bool capped) {
  SubprocessLimits l;
  l.timeout_seconds = 20;
  l.memory_mb = capped ? std::size_t{1} << 20 : 0;
  return l;
}

const char* path_name(bool capped) { return capped ? "fork (memory cap)" : "posix_spawn (no cap)"; }

// A program that says on stderr how it was started: its pid and process group, what
// stdin reads, where stdout goes, its directory.
const std::string kReport =
    "/usr/bin/python3 -c 'import os, sys; "
    "sys.stderr.write(\"%d %d [%s] %s %s\" % (os.getpid(), os.getpgid(0), sys.stdin.read(), "
    "os.path.realpath(\"/proc/self/fd/1\"), os.getcwd()))'";
// The signals it ignores, SigIgn's mask in hex (awk, which sets none of its own; Python
// ignores SIGPIPE itself).
const std::string kIgnored = "/usr/bin/awk '/^SigIgn/ { print $2 > \"/dev/stderr\" }' /proc/self/status";

struct Report {
  long pid = 0, group = 0;
  std::string stdin_text, stdout_path, cwd;
};

Report parse(const std::string& text) {
  Report r;
  std::istringstream in(text);
  in >> r.pid >> r.group >> r.stdin_text >> r.stdout_path >> r.cwd;
  return r;
}

TEST(ChildPaths, BothPathsStartTheChildAlike) {
  const fs::path dir = fs::temp_directory_path() / ("lepp-child-paths-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // The parent ignores all three: the child must not inherit that.
  struct sigaction ignore {}, saved[3];
  ignore.sa_handler = SIG_IGN;
  const int sigs[3] = {SIGINT, SIGTERM, SIGPIPE};
  for (int i = 0; i < 3; ++i) sigaction(sigs[i], &ignore, &saved[i]);
  // The parent's stdin has bytes to read and its stdout is a file (under ctest both may
  // be /dev/null already, which would hide a child that kept them).
  const int kept_in = ::dup(0), kept_out = ::dup(1);
  int feed[2];
  ASSERT_EQ(::pipe(feed), 0);
  ASSERT_EQ(::write(feed[1], "parent-input\n", 13), 13);
  ::close(feed[1]);
  ::dup2(feed[0], 0);
  ::close(feed[0]);
  const fs::path out_file = dir / "parent-stdout";
  const int out = ::open(out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  ::dup2(out, 1);
  ::close(out);
  // The runs first, judged once the test's own stdin and stdout are back (gtest prints there).
  struct Run {
    std::string where;
    SubprocessResult report, ignored;
  };
  std::vector<Run> runs;
  for (bool capped : {false, true}) {
    SubprocessLimits l = limits_for(capped);
    l.directory = dir.string();
    for (bool shell : {false, true})
      runs.push_back({std::string(path_name(capped)) + (shell ? ", by sh" : ", direct"),
                      shell ? run_shell_command(kReport, l) : run_subprocess(kReport, l),
                      shell ? run_shell_command(kIgnored, l) : run_subprocess(kIgnored, l)});
  }
  std::fflush(stdout);
  ::dup2(kept_in, 0);
  ::dup2(kept_out, 1);
  ::close(kept_in);
  ::close(kept_out);
  for (const Run& run : runs) {
    const std::string where = run.where + ": " + run.report.stderr_text;
    EXPECT_EQ(run.report.exit_code, 0) << where;
    const Report rep = parse(run.report.stderr_text);
    if (run.where.find("by sh") == std::string::npos) EXPECT_EQ(rep.group, rep.pid) << where;  // sh leads its child's group
    EXPECT_EQ(rep.stdin_text, "[]") << where;
    EXPECT_EQ(rep.stdout_path, "/dev/null") << where;
    EXPECT_EQ(fs::path(rep.cwd), fs::canonical(dir)) << where;
    EXPECT_EQ(run.ignored.exit_code, 0) << run.where << "; " << run.ignored.stderr_text;
    if (run.ignored.exit_code != 0) continue;
    const unsigned long long mask = (1ull << (SIGINT - 1)) | (1ull << (SIGTERM - 1)) | (1ull << (SIGPIPE - 1));
    EXPECT_EQ(std::stoull(run.ignored.stderr_text, nullptr, 16) & mask, 0u) << run.where << "; SigIgn " << run.ignored.stderr_text;
  }
  for (int i = 0; i < 3; ++i) sigaction(sigs[i], &saved[i], nullptr);
  fs::remove_all(dir);
}

TEST(ChildPaths, ADirectoryItCannotEnterIs126AndSaysNothing) {
  for (bool capped : {false, true}) {
    SubprocessLimits l = limits_for(capped);
    l.directory = "/no/such/directory/for/lepp";
    for (bool shell : {false, true}) {
      const SubprocessResult r = shell ? run_shell_command("true", l) : run_subprocess("/bin/true", l);
      EXPECT_TRUE(r.started) << path_name(capped);
      EXPECT_EQ(r.exit_code, 126) << path_name(capped) << (shell ? ", by sh" : "");
      EXPECT_EQ(r.stderr_text, "") << path_name(capped) << (shell ? ", by sh" : "");
    }
  }
}

TEST(ChildPaths, AProgramThatCannotRunEndsAsUnderSh) {
  const fs::path dir = fs::temp_directory_path() / ("lepp-child-paths-x-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / "not-executable";
  std::ofstream(file) << "#!/bin/sh\nexit 0\n";
  ::chmod(file.c_str(), 0644);
  for (bool capped : {false, true}) {
    const SubprocessLimits l = limits_for(capped);
    const SubprocessResult missing = run_subprocess("no-such-mesher-anywhere a", l);
    EXPECT_EQ(missing.exit_code, 127) << path_name(capped);
    EXPECT_EQ(missing.stderr_text, "no-such-mesher-anywhere: not found\n") << path_name(capped);
    const SubprocessResult absent = run_subprocess("/no/such/mesher a", l);
    EXPECT_EQ(absent.exit_code, 127) << path_name(capped);
    EXPECT_EQ(absent.stderr_text, "/no/such/mesher: not found\n") << path_name(capped);
    const SubprocessResult denied = run_subprocess(file.string() + " x", l);
    EXPECT_EQ(denied.exit_code, 126) << path_name(capped);
    EXPECT_EQ(denied.stderr_text, file.string() + ": Permission denied\n") << path_name(capped);
  }
  fs::remove_all(dir);
}

TEST(ChildPaths, ATimeoutKillsWhatTheChildStartedEitherWay) {
  for (bool capped : {false, true}) {
    SubprocessLimits l = limits_for(capped);
    l.timeout_seconds = 0.5;
    // A background grandchild holding stderr open: killed with the group.
    const SubprocessResult r = run_shell_command("sleep 30 & sleep 30", l);
    EXPECT_TRUE(r.timed_out) << path_name(capped);
    EXPECT_LT(r.seconds, 15) << path_name(capped);
  }
}

}  // namespace
