// SPDX-License-Identifier: GPL-3.0-or-later
// Runs one shell command as the audit needs it: /bin/sh -c in its own process
// group, stdout discarded, stderr kept (capped), the whole group killed at the
// timeout, the address space capped with setrlimit(RLIMIT_AS) in the child.
// Never blocks past the timeout, whatever the command does (forks, closes or
// keeps stderr open, ignores SIGTERM).
#pragma once
#include <cstddef>
#include <string>

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
  double seconds = 0;
  std::string detail;
};

SubprocessResult run_subprocess(const std::string& shell_command, const SubprocessLimits& limits);

// Single-quotes s for /bin/sh.
std::string shell_quote(const std::string& s);

}  // namespace lepp::audit
