// SPDX-License-Identifier: GPL-3.0-or-later
// Runs one command line, or one function in a forked child, as the audit needs
// it: its own process group, stdin and stdout on /dev/null, stderr kept (capped),
// the whole group killed at the timeout, the address space capped with
// setrlimit(RLIMIT_AS) in the child. Never blocks past the timeout, whatever the
// child does (forks, closes or keeps stderr open, ignores SIGTERM, loops). A command
// with no memory cap starts by posix_spawn (none of the caller's page tables copied,
// which for a large or sanitized caller was most of a short run's cost); with a cap,
// by fork, to set it. Either way the child starts alike.
#pragma once
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace lepp::audit {

struct SubprocessLimits {
  double timeout_seconds = 10;       // <= 0: no timeout
  std::size_t memory_mb = 0;         // 0: no cap
  std::size_t stderr_cap = 64 * 1024;  // bytes of stderr kept; the rest is read and dropped
  std::string directory;             // working directory of the command; empty: ours
};

struct SubprocessResult {
  bool started = false;   // false: fork or pipe failed (detail says why)
  bool timed_out = false;
  int exit_code = -1;     // when it exited
  int signal = 0;         // when a signal ended it (SIGKILL after a timeout included)
  std::string stderr_text;
  bool stderr_truncated = false;
  std::string output;     // run_forked: every byte the child wrote to its result pipe (not capped)
  double seconds = 0;
  std::string detail;
};

// Runs a command line as `/bin/sh -c shell_command` would. A command that is only
// words (shell_words.h: the command adapter's templates mostly are) runs as
// run_program runs them, without the shell; any other, by run_shell_command.
SubprocessResult run_subprocess(const std::string& shell_command, const SubprocessLimits& limits);

// `/bin/sh -c shell_command`, always.
SubprocessResult run_shell_command(const std::string& shell_command, const SubprocessLimits& limits);

// The program words[0] (searched in PATH when it has no '/', execvp) with the
// arguments words[1...]. One it cannot run ends as sh reports it: exit 127 and
// "PROGRAM: not found" on stderr when it is not there, 126 when it is but cannot
// be executed. A file without "#!" runs as a shell script, as under sh. Its
// environment is ours, with PWD set as sh sets it (the working directory's
// physical path, when ours does not name that directory).
SubprocessResult run_program(const std::vector<std::string>& words, const SubprocessLimits& limits);

// What a forked child runs, after the limits are set: it may write its result to
// result_fd (read by the parent while it runs, into SubprocessResult::output) and
// returns its exit status. It must not return into the caller's code: run_forked
// ends the child with _exit (status 125 if the function throws). Fork without
// exec: with `-j` other threads of the audit may be running; the child has only
// the forking thread, and glibc's fork keeps malloc usable in it; a function
// that waited on a lock another thread held at the fork would hang until the
// timeout kills it (a "timed out" run). isolated_engine (isolated_engine.h) forks
// its children from a fork server made before the threads instead.
using ChildFunction = std::function<int(int result_fd)>;

// Runs `child` in a forked process under the same rules and the same wait loop
// as run_subprocess (which is run_forked with a child that execs the program, or /bin/sh).
SubprocessResult run_forked(const ChildFunction& child, const SubprocessLimits& limits);

// Single-quotes s for /bin/sh.
std::string shell_quote(const std::string& s);

}  // namespace lepp::audit
