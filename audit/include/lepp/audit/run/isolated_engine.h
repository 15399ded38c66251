// SPDX-License-Identifier: GPL-3.0-or-later
// Any in-process engine run in a forked child, so that the audit survives it:
// an engine that never returns is killed at the request's timeout (SIGKILL,
// RunStatus::TimedOut), one that crashes (a signal: segfault, abort, a failed
// assertion) or throws is RunStatus::Crashed, and request.memory_mb caps what it
// may allocate. The child's EngineRun comes back whole through a pipe
// (engine_run_bytes.h); a child that ends without sending one whole is Crashed,
// ExitCode or UnreadableOutput, never a partial mesh.
#pragma once
#include "lepp/audit/engine.h"

namespace lepp::audit {

// The returned engine runs `inner` in a child process with the request
// unchanged, and waits for it at most request.timeout_seconds of wall clock (0:
// no limit). The children are forked by a fork server, a process forked when
// isolated_engine is called (fork_server.cpp): call it before starting threads.
// A child forked from a threaded process has only the forking thread, and every
// lock another thread held at the fork (in the C++ runtime, CGAL, a sanitizer's
// allocator) stays held in it forever; the server has one thread, so its
// children start from a quiet copy of the process as it was at the call.
// Its EngineRun is the child's, field for field, except:
//   - seconds: the run's wall-clock time as the parent sees it (the fork and the
//     transfers both ways included);
//   - stderr_text: the child's, followed by whatever the child wrote on its
//     standard error (capped at 64 KB), e.g. a failed assertion's message.
// memory_mb > 0 caps the child's address space at memory_mb MB above what it
// starts with (setrlimit(RLIMIT_AS)); an allocation past it fails in the child
// (std::bad_alloc: Crashed with the message, or a signal). The child writes no
// core file. The engine may be called from several threads at once (lepp audit
// -j N); if the server cannot be started, every run is Crashed, saying why.
Engine isolated_engine(Engine inner);

// Whether a child forked while other threads of the parent run may allocate.
// glibc's malloc takes its locks around fork, so it may; the AddressSanitizer
// runtime of GCC 12 does not: a child forked while another thread holds one of
// its allocator's locks waits on it forever (in the sanitizer build, isolated
// runs of -j 2 audits once timed out at random: 35 of 40 audits of the paper's
// problems). isolated_engine no longer forks beside threads (its fork server),
// and the audit no longer asks; kept for code that forks on its own.
constexpr bool fork_safe_with_threads() {
#if defined(__SANITIZE_ADDRESS__)
  return false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  return false;
#else
  return true;
#endif
#else
  return true;
#endif
}

}  // namespace lepp::audit
