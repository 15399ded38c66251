// SPDX-License-Identifier: GPL-3.0-or-later
// An in-process engine run in a child process: timeout, crashes, memory cap.
#include "lepp/audit/run/isolated_engine.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>
#include <utility>

#include <fmt/format.h>

#include "lepp/audit/run/engine_run_bytes.h"
#include "lepp/audit/run/subprocess.h"
#include "fork_server.h"

namespace lepp::audit {
namespace {

// Exit status of a child that could not send its run back (it says why on stderr).
constexpr int kSendFailed = 125;

// The parent's address space now, in MB (what a forked child starts with); 0 if unknown.
std::size_t address_space_mb() {
  std::ifstream statm("/proc/self/statm");
  std::size_t pages = 0;
  if (!(statm >> pages)) return 0;
  return pages * static_cast<std::size_t>(sysconf(_SC_PAGESIZE)) / (1024 * 1024) + 1;
}

bool write_all(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

// In the child: the engine's run, or a Crashed run if it threw, sent to the parent.
int run_and_send(const Engine& inner, const Pslg& pslg, const EngineRequest& req, int result_fd) {
  struct rlimit no_core{0, 0};
  setrlimit(RLIMIT_CORE, &no_core);
  EngineRun run;
  try {
    run = inner(pslg, req);
  } catch (const std::exception& e) {
    run = EngineRun{};
    run.status = RunStatus::Crashed;
    run.detail = std::string("exception: ") + e.what();
  } catch (...) {
    run = EngineRun{};
    run.status = RunStatus::Crashed;
    run.detail = "exception of unknown type";
  }
  try {
    if (write_all(result_fd, encode_engine_run(run))) return 0;
    dprintf(2, "isolated engine: cannot send the run back: %s\n", std::strerror(errno));
  } catch (const std::exception& e) {
    dprintf(2, "isolated engine: cannot send the run back: %s\n", e.what());
  }
  return kSendFailed;
}

std::string first_line(const std::string& text) {
  std::string first = text.substr(0, text.find('\n'));
  return first.substr(0, 200);
}

std::string with_stderr(std::string detail, const std::string& stderr_text) {
  std::string first = first_line(stderr_text);
  return first.empty() ? detail : detail + ": " + first;
}

}  // namespace

Engine isolated_engine(Engine inner) {
  // The server is forked now, before the audit's threads: its children start quiet (fork_server.h).
  std::shared_ptr<ForkServer> server;
  std::string no_server;
  try {
    server = std::make_shared<ForkServer>([inner = std::move(inner)](const Pslg& pslg, const EngineRequest& req, int fd) {
      if (req.memory_mb > 0) {
        struct rlimit rl;
        rl.rlim_cur = rl.rlim_max = static_cast<rlim_t>(req.memory_mb + address_space_mb()) * 1024 * 1024;
        setrlimit(RLIMIT_AS, &rl);
      }
      return run_and_send(inner, pslg, req, fd);
    });
  } catch (const std::exception& e) {
    no_server = e.what();
  }
  return [server, no_server](const Pslg& pslg, const EngineRequest& req) {
    SubprocessLimits limits;
    limits.timeout_seconds = req.timeout_seconds;
    SubprocessResult sr;
    if (server) sr = server->run(pslg, req, limits);
    else sr.detail = no_server;
    EngineRun run;
    if (!sr.started) {
      run.status = RunStatus::Crashed;
      run.detail = "cannot start the isolated engine: " + sr.detail;
      return run;
    }
    run.seconds = sr.seconds;
    run.stderr_text = sr.stderr_text;
    if (sr.timed_out) {
      run.status = RunStatus::TimedOut;
      run.detail = fmt::format("killed after {:.3g} s (in-process engine, isolated)", req.timeout_seconds);
      return run;
    }
    if (sr.signal != 0) {
      run.status = RunStatus::Crashed;
      run.signal = sr.signal;
      run.detail = with_stderr(fmt::format("killed by signal {} ({})", sr.signal, strsignal(sr.signal)), sr.stderr_text);
      return run;
    }
    if (sr.exit_code == -1 && !sr.detail.empty()) {
      run.status = RunStatus::Crashed;
      run.detail = sr.detail;
      return run;
    }
    if (sr.exit_code != 0) {
      // The engine called exit(), or the child could not send its run (kSendFailed, said on stderr).
      run.status = sr.exit_code == kSendFailed ? RunStatus::Crashed : RunStatus::ExitCode;
      run.exit_code = sr.exit_code;
      run.detail = with_stderr(fmt::format("exit status {} before the run came back", sr.exit_code), sr.stderr_text);
      return run;
    }
    try {
      run = decode_engine_run(sr.output);
    } catch (const std::exception& e) {
      run = EngineRun{};
      run.status = RunStatus::UnreadableOutput;
      run.detail = sr.output.empty() ? std::string("the engine's process exited before returning a run") : e.what();
      run.stderr_text = sr.stderr_text;
      run.seconds = sr.seconds;
      return run;
    }
    run.seconds = sr.seconds;
    run.stderr_text += sr.stderr_text;
    return run;
  };
}

}  // namespace lepp::audit
