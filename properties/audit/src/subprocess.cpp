// SPDX-License-Identifier: GPL-3.0-or-later
#include "lepp/audit/subprocess.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>

namespace lepp::audit {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// In the child after fork: only async-signal-safe calls until exec.
[[noreturn]] void exec_child(const char* command, int stderr_fd, const SubprocessLimits& limits) {
  setpgid(0, 0);  // its own group, so a timeout kills everything it started
  // Default signal handling in the child whatever the parent set.
  signal(SIGPIPE, SIG_DFL);
  signal(SIGINT, SIG_DFL);
  signal(SIGTERM, SIG_DFL);
  int devnull = open("/dev/null", O_RDWR);
  if (devnull >= 0) {
    dup2(devnull, 0);
    dup2(devnull, 1);
    if (devnull > 2) close(devnull);
  }
  dup2(stderr_fd, 2);
  if (stderr_fd > 2) close(stderr_fd);
  if (!limits.directory.empty() && chdir(limits.directory.c_str()) != 0) _exit(126);
  if (limits.memory_mb > 0) {
    struct rlimit rl;
    rl.rlim_cur = rl.rlim_max = static_cast<rlim_t>(limits.memory_mb) * 1024 * 1024;
    setrlimit(RLIMIT_AS, &rl);
  }
  execl("/bin/sh", "sh", "-c", command, static_cast<char*>(nullptr));
  _exit(127);
}

}  // namespace

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

SubprocessResult run_subprocess(const std::string& shell_command, const SubprocessLimits& limits) {
  SubprocessResult r;
  int fds[2];
  if (pipe(fds) != 0) {
    r.detail = std::string("pipe: ") + std::strerror(errno);
    return r;
  }
  fcntl(fds[0], F_SETFD, FD_CLOEXEC);
  const auto t0 = Clock::now();
  pid_t pid = fork();
  if (pid < 0) {
    r.detail = std::string("fork: ") + std::strerror(errno);
    close(fds[0]);
    close(fds[1]);
    return r;
  }
  if (pid == 0) exec_child(shell_command.c_str(), fds[1], limits);
  setpgid(pid, pid);  // also here: no race with the kill below
  close(fds[1]);
  fcntl(fds[0], F_SETFL, O_NONBLOCK);
  r.started = true;

  bool pipe_open = true, exited = false;
  int wstatus = 0;
  char buf[4096];
  auto drain = [&] {
    while (pipe_open) {
      ssize_t n = read(fds[0], buf, sizeof buf);
      if (n > 0) {
        std::size_t room = limits.stderr_cap > r.stderr_text.size() ? limits.stderr_cap - r.stderr_text.size() : 0;
        std::size_t take = std::min(room, static_cast<std::size_t>(n));
        r.stderr_text.append(buf, take);
        if (take < static_cast<std::size_t>(n)) r.stderr_truncated = true;
      } else if (n == 0) {
        pipe_open = false;
      } else {
        if (errno == EINTR) continue;
        if (errno != EAGAIN && errno != EWOULDBLOCK) pipe_open = false;
        return;
      }
    }
  };
  while (!exited) {
    double left = limits.timeout_seconds > 0 ? limits.timeout_seconds - since(t0) : 1e9;
    if (left <= 0) {
      r.timed_out = true;
      kill(-pid, SIGKILL);
      waitpid(pid, &wstatus, 0);
      exited = true;
      break;
    }
    // Wake at least every 50 ms to reap the child even if a grandchild keeps stderr open.
    int wait_ms = static_cast<int>(std::min(left * 1000 + 1, 50.0));
    if (pipe_open) {
      struct pollfd p{fds[0], POLLIN, 0};
      int k = poll(&p, 1, wait_ms);
      if (k > 0) drain();
    } else {
      usleep(static_cast<useconds_t>(std::min(wait_ms, 5)) * 1000);
    }
    pid_t w = waitpid(pid, &wstatus, WNOHANG);
    if (w == pid) exited = true;
  }
  r.seconds = since(t0);
  drain();
  // Whatever the shell left behind in its group (background jobs) goes too.
  kill(-pid, SIGKILL);
  close(fds[0]);
  if (!r.timed_out) {
    if (WIFEXITED(wstatus)) r.exit_code = WEXITSTATUS(wstatus);
    if (WIFSIGNALED(wstatus)) r.signal = WTERMSIG(wstatus);
  } else {
    r.signal = SIGKILL;
  }
  return r;
}

}  // namespace lepp::audit
