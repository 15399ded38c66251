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

// The returned engine runs `inner` in a child process (run_forked, subprocess.h)
// with the request unchanged, and waits for it at most request.timeout_seconds
// of wall clock (0: no limit). Its EngineRun is the child's, field for field,
// except:
//   - seconds: the run's wall-clock time as the parent sees it (fork and the
//     transfer back included);
//   - stderr_text: the child's, followed by whatever the child wrote on its
//     standard error (capped at 64 KB), e.g. a failed assertion's message.
// memory_mb > 0 caps the child's address space at memory_mb MB above what it
// inherits from the parent at the fork (setrlimit(RLIMIT_AS)); an allocation past
// it fails in the child (std::bad_alloc: Crashed with the message, or a signal).
// The child writes no core file. It may be called from several threads at once
// (lepp audit -j N) where fork is safe with threads: see fork_safe_with_threads().
Engine isolated_engine(Engine inner);

// Whether a child forked while other threads of the parent run may allocate.
// glibc's malloc takes its locks around fork, so it may; the AddressSanitizer
// runtime of GCC 12 does not: a child forked while another thread holds one of
// its allocator's locks waits on it forever (in the sanitizer build, isolated
// runs of -j 2 audits timed out at random: 35 of 40 audits of the paper's
// problems, 0 of 60 in Release). An audit runs one job by default there
// (resolve_jobs, parallel.h: the CLI, Python and run_audit alike).
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
