// SPDX-License-Identifier: GPL-3.0-or-later
// What run_forked (subprocess.h) and the fork server (fork_server.h) share: the
// child's set-up after fork, and the parent's wait loop, which learns the child's
// end from waitpid (its own child) or from the server (a child of the server).
#pragma once
#include <sys/types.h>

#include <chrono>
#include <string>

#include "lepp/audit/run/subprocess.h"

namespace lepp::audit {

// In the child after fork, before its function runs (only async-signal-safe
// calls): its own process group, default signals, stdin and stdout on /dev/null,
// stderr_fd as stderr, limits.directory, the address space capped at memory_mb.
void set_up_child(int stderr_fd, const SubprocessLimits& limits);

// How the wait loop learns that its child has ended.
class ChildEnd {
 public:
  virtual ~ChildEnd() = default;
  // 1: ended, *wstatus as waitpid gives it; 0: still running; -1: ended, but how is
  // lost (*detail says why).
  virtual int poll(int* wstatus, std::string* detail) = 0;
  // After the SIGKILL of a timeout: waits until it has ended.
  virtual void wait(int* wstatus) = 0;
};

// Reads the child's stderr (capped) and result pipes until it ends or the timeout
// (from t0) kills its process group; then kills whatever is left in the group and
// closes both read ends. Fills every field of r but started.
void wait_for_child(pid_t pid, int err_fd, int res_fd, const SubprocessLimits& limits,
                    std::chrono::steady_clock::time_point t0, ChildEnd& end, SubprocessResult& r);

}  // namespace lepp::audit
