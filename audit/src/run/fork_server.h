// SPDX-License-Identifier: GPL-3.0-or-later
// A fork server for isolated_engine (isolated_engine.h): one process, forked when
// the isolated engine is made, that forks a child per run of the engine.
//
// Why: `lepp audit -j N` runs several threads, and a child forked from a threaded
// process has only the forking thread; any lock another thread held at the fork
// (in the C++ runtime, CGAL, GMP, the sanitizer's allocator, the program's own)
// stays held forever in the child, and an engine run that needs it never ends.
// The server is forked before the audit starts its threads and has only one
// thread, so its children start from a quiet copy. A run sends the PSLG and the
// request (engine_run_bytes.h) with its three pipe ends (stderr, result, end
// status); the server forks, the child runs the engine as run_forked's children
// do, and the server reports the child's pid and, when it has reaped it, its
// wait status.
#pragma once
#include <sys/types.h>

#include <functional>
#include <mutex>

#include "lepp/audit/engine.h"
#include "lepp/audit/run/subprocess.h"

namespace lepp::audit {

class ForkServer {
 public:
  // What a child of the server runs: the call, and where to write its result;
  // returns the child's exit status.
  using Body = std::function<int(const Pslg& pslg, const EngineRequest& req, int result_fd)>;

  // Forks the server now (make it while the process has one thread); throws
  // std::runtime_error if it cannot.
  explicit ForkServer(Body body);
  ~ForkServer();  // ends the server (it has no run left: each run holds the server)
  ForkServer(const ForkServer&) = delete;
  ForkServer& operator=(const ForkServer&) = delete;

  // One run of the body in a child of the server, waited for as run_forked waits
  // (limits: timeout and stderr cap; a memory cap is the body's to set). May be
  // called from several threads at once.
  SubprocessResult run(const Pslg& pslg, const EngineRequest& req, const SubprocessLimits& limits);

 private:
  int control_ = -1;  // our end of the server's socket
  pid_t server_ = -1;
  std::mutex send_;   // one request on the socket at a time
};

}  // namespace lepp::audit
