// SPDX-License-Identifier: GPL-3.0-or-later
// One command (directly when it is only words, else by /bin/sh) or forked function run
// with a process group, a timeout, a memory cap and capped stderr.
#include "lepp/audit/run/subprocess.h"

#include "child_process.h"
#include "lepp/audit/run/shell_words.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <system_error>
#include <vector>

namespace lepp::audit {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// The read end of a pipe from the child, emptied without blocking.
struct PipeReader {
  int fd = -1;
  bool open = true;
  std::string* text = nullptr;
  std::size_t cap = 0;  // 0: no cap
  bool truncated = false;

  void drain() {
    char buf[65536];
    while (open) {
      ssize_t n = read(fd, buf, sizeof buf);
      if (n > 0) {
        std::size_t room = cap == 0 ? static_cast<std::size_t>(n) : cap > text->size() ? cap - text->size() : 0;
        std::size_t take = std::min(room, static_cast<std::size_t>(n));
        text->append(buf, take);
        if (take < static_cast<std::size_t>(n)) truncated = true;
      } else if (n == 0) {
        open = false;
      } else {
        if (errno == EINTR) continue;
        if (errno != EAGAIN && errno != EWOULDBLOCK) open = false;
        return;
      }
    }
  }
};

// A process that inherited SIGCHLD ignored (SIG_IGN, or SA_NOCLDWAIT: it survives
// exec, and some launchers and CI runners leave it so) has its children reaped by the
// kernel, and waitpid never sees one end: every run would last until its timeout, or
// forever without one. The audit waits for its own children, so it restores the default.
void let_us_reap_our_children() {
  struct sigaction sa;
  if (sigaction(SIGCHLD, nullptr, &sa) != 0) return;
  if (sa.sa_handler != SIG_IGN && !(sa.sa_flags & SA_NOCLDWAIT)) return;
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  sigaction(SIGCHLD, &dfl, nullptr);
}

bool make_pipe(int fds[2], std::string& detail) {
  // Close-on-exec from the start (pipe2): nothing the child execs inherits them (its
  // stderr is a dup2 copy, which is), nor a program another audit thread starts meanwhile.
  if (pipe2(fds, O_CLOEXEC) != 0) {
    detail = std::string("pipe: ") + std::strerror(errno);
    return false;
  }
  return true;
}

// The child's stderr and result pipes, both or neither.
bool make_pipes(int err[2], int res[2], std::string& detail) {
  if (!make_pipe(err, detail)) return false;
  if (make_pipe(res, detail)) return true;
  close(err[0]);
  close(err[1]);
  return false;
}

// The child's end as waitpid sees it (the child is ours).
class WaitpidEnd : public ChildEnd {
 public:
  explicit WaitpidEnd(pid_t pid) : pid_(pid) {}
  int poll(int* wstatus, std::string* detail) override {
    pid_t w = waitpid(pid_, wstatus, WNOHANG);
    if (w == pid_) return 1;
    if (w < 0 && errno != EINTR) {
      // Not ours to wait for any more (reaped elsewhere): its end is unknown, but it has ended.
      *detail = std::string("waitpid: ") + std::strerror(errno) + ": the child's exit status is lost";
      return -1;
    }
    return 0;
  }
  void wait(int* wstatus) override { waitpid(pid_, wstatus, 0); }

 private:
  pid_t pid_;
};

// The environment sh would give the program: sh (dash, Debian's) sets PWD to the
// working directory when the inherited PWD does not name it (stale, relative or
// unset). Empty when the environment needs no change.
std::vector<std::string> environment_as_sh_gives_it(const std::string& directory) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path here = directory.empty() ? fs::path(".") : fs::path(directory);
  const char* pwd = std::getenv("PWD");
  if (pwd && pwd[0] == '/' && fs::equivalent(pwd, here, ec)) return {};
  const fs::path physical = fs::canonical(here, ec);
  if (ec) return {};  // sh would not start there either: the child's chdir fails first
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e)
    if (std::strncmp(*e, "PWD=", 4) != 0) env.emplace_back(*e);
  env.push_back("PWD=" + physical.string());
  return env;
}

}  // namespace

// In the child after fork, before its function runs: only async-signal-safe calls.
void set_up_child(int stderr_fd, const SubprocessLimits& limits) {
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
}

void wait_for_child(pid_t pid, int err_fd, int res_fd, const SubprocessLimits& limits,
                    std::chrono::steady_clock::time_point t0, ChildEnd& end, SubprocessResult& r) {
  fcntl(err_fd, F_SETFL, O_NONBLOCK);
  fcntl(res_fd, F_SETFL, O_NONBLOCK);
  PipeReader stderr_pipe{err_fd, true, &r.stderr_text, limits.stderr_cap};
  PipeReader result_pipe{res_fd, true, &r.output, 0};
  bool exited = false, lost = false;
  int wstatus = 0;
  int nap_us = 50;
  while (!exited) {
    double left = limits.timeout_seconds > 0 ? limits.timeout_seconds - since(t0) : 1e9;
    if (left <= 0) {
      r.timed_out = true;
      kill(-pid, SIGKILL);
      end.wait(&wstatus);
      exited = true;
      break;
    }
    // Wake at least every 50 ms to reap the child even if a grandchild keeps a pipe open.
    int wait_ms = static_cast<int>(std::min(left * 1000 + 1, 50.0));
    struct pollfd p[2];
    nfds_t n = 0;
    for (PipeReader* pr : {&stderr_pipe, &result_pipe})
      if (pr->open) p[n++] = {pr->fd, POLLIN, 0};
    if (n > 0) {
      if (poll(p, n, wait_ms) > 0) {
        stderr_pipe.drain();
        result_pipe.drain();
      }
    } else {
      // Both pipes closed: the child is most likely exiting. Look again soon, then less often.
      usleep(static_cast<useconds_t>(std::min(static_cast<double>(nap_us), left * 1e6 + 1)));
      nap_us = std::min(nap_us * 2, 5000);
    }
    const int e = end.poll(&wstatus, &r.detail);
    if (e != 0) exited = true;
    if (e < 0) lost = true;
  }
  r.seconds = since(t0);
  stderr_pipe.drain();
  result_pipe.drain();
  r.stderr_truncated = stderr_pipe.truncated;
  // Whatever the child left behind in its group (background jobs) goes too.
  kill(-pid, SIGKILL);
  close(err_fd);
  close(res_fd);
  if (lost) {
    r.exit_code = -1;
  } else if (!r.timed_out) {
    if (WIFEXITED(wstatus)) r.exit_code = WEXITSTATUS(wstatus);
    if (WIFSIGNALED(wstatus)) r.signal = WTERMSIG(wstatus);
  } else {
    r.signal = SIGKILL;
  }
}

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

SubprocessResult run_forked(const ChildFunction& child, const SubprocessLimits& limits) {
  SubprocessResult r;
  let_us_reap_our_children();
  int err[2], res[2];
  if (!make_pipes(err, res, r.detail)) return r;
  const auto t0 = Clock::now();
  pid_t pid = fork();
  if (pid < 0) {
    r.detail = std::string("fork: ") + std::strerror(errno);
    for (int fd : {err[0], err[1], res[0], res[1]}) close(fd);
    return r;
  }
  if (pid == 0) {
    close(err[0]);
    close(res[0]);
    set_up_child(err[1], limits);
    int status = 125;
    try {
      status = child(res[1]);
    } catch (...) {
    }
    _exit(status);  // never back into the caller's code, nor its atexit handlers and stdio buffers
  }
  setpgid(pid, pid);  // also here: no race with the kill below
  close(err[1]);
  close(res[1]);
  r.started = true;

  WaitpidEnd end(pid);
  wait_for_child(pid, err[0], res[0], limits, t0, end, r);
  return r;
}

namespace {

// How sh reports a program it cannot run, by exec's errno: kind 0 not there (127, "not
// found"), 1 not permitted (126), 2 anything else (126). Both children use it; the forked
// one after fork, so it only reads these tables.
int exec_failure(int e) { return e == ENOENT || e == ENOTDIR ? 0 : e == EACCES ? 1 : 2; }
constexpr const char* kExecFailureSaid[3] = {": not found\n", ": Permission denied\n", ": cannot execute\n"};
constexpr int kExecFailureStatus[3] = {127, 126, 126};

// The working directory a child could not enter (posix_spawn gives chdir's error and
// exec's alike).
bool chdir_fails(const std::string& directory) {
  std::error_code ec;
  return !std::filesystem::is_directory(directory, ec) || access(directory.c_str(), X_OK) != 0;
}

// run_forked's child, made by posix_spawn: glibc's clone(CLONE_VM | CLONE_VFORK) copies
// none of the parent's page tables, which fork copies and exec then unmaps (a sixth of
// fuzz_engine's samples under ASan, whose shadow maps are large, and copy-on-write faults
// besides; an audit's parent is big too). The same set-up as set_up_child's but the
// memory cap, which posix_spawn cannot set: a run with one forks. A program that cannot
// run ends as run_program's child ends (127 and "PROGRAM: not found", 126 otherwise);
// here posix_spawn reports it instead.
// `name`: the program as its error message names it; null for /bin/sh's, which says nothing.
SubprocessResult run_spawned(const char* file, char* const argv[], char* const envp[], bool search,
                             const SubprocessLimits& limits, const std::string* name) {
  SubprocessResult r;
  let_us_reap_our_children();
  int err[2], res[2];
  if (!make_pipes(err, res, r.detail)) return r;
  close(res[1]);  // a program has no result pipe: the parent reads its end at once
  posix_spawn_file_actions_t actions;
  posix_spawnattr_t attr;
  posix_spawn_file_actions_init(&actions);
  posix_spawnattr_init(&attr);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDWR, 0);
  posix_spawn_file_actions_adddup2(&actions, 0, 1);
  posix_spawn_file_actions_adddup2(&actions, err[1], 2);  // dup2 clears close-on-exec on 2
  if (!limits.directory.empty()) posix_spawn_file_actions_addchdir_np(&actions, limits.directory.c_str());
  sigset_t defaults;
  sigemptyset(&defaults);
  for (int sig : {SIGPIPE, SIGINT, SIGTERM}) sigaddset(&defaults, sig);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  posix_spawnattr_setpgroup(&attr, 0);  // its own group, so a timeout kills everything it started
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGDEF);
  const auto t0 = Clock::now();
  pid_t pid = -1;
  const int e = search ? posix_spawnp(&pid, file, &actions, &attr, argv, envp)
                       : posix_spawn(&pid, file, &actions, &attr, argv, envp);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attr);
  close(err[1]);
  if (e != 0) {
    close(err[0]);
    close(res[0]);
    // The child ended before its exec: as run_forked's child would have. Its chdir failed
    // (126, nothing said), or its exec (run_program's child: 127 and "not found", 126
    // otherwise, said on stderr; /bin/sh's: 127, nothing said).
    r.started = true;
    r.seconds = since(t0);
    const bool chdir_failed = !limits.directory.empty() && chdir_fails(limits.directory);
    const int kind = exec_failure(e);
    r.exit_code = chdir_failed ? 126 : !name ? 127 : kExecFailureStatus[kind];
    if (!chdir_failed && name) r.stderr_text = *name + kExecFailureSaid[kind];
    return r;
  }
  r.started = true;
  WaitpidEnd end(pid);
  wait_for_child(pid, err[0], res[0], limits, t0, end, r);
  return r;
}

}  // namespace

SubprocessResult run_shell_command(const std::string& shell_command, const SubprocessLimits& limits) {
  const char* command = shell_command.c_str();
  if (limits.memory_mb == 0) {
    char* const argv[] = {const_cast<char*>("sh"), const_cast<char*>("-c"), const_cast<char*>(command), nullptr};
    return run_spawned("/bin/sh", argv, environ, false, limits, nullptr);
  }
  return run_forked(
      [command](int) {
        execl("/bin/sh", "sh", "-c", command, static_cast<char*>(nullptr));
        return 127;
      },
      limits);
}

SubprocessResult run_program(const std::vector<std::string>& words, const SubprocessLimits& limits) {
  // Everything the child needs is made here: after fork it only calls execvp(e) and write.
  std::vector<char*> argv;
  for (const std::string& w : words) argv.push_back(const_cast<char*>(w.c_str()));
  argv.push_back(nullptr);
  const std::vector<std::string> env = environment_as_sh_gives_it(limits.directory);
  std::vector<char*> envp;
  for (const std::string& e : env) envp.push_back(const_cast<char*>(e.c_str()));
  envp.push_back(nullptr);
  if (limits.memory_mb == 0) return run_spawned(argv[0], argv.data(), env.empty() ? environ : envp.data(), true, limits, &words.at(0));
  std::string said[3];
  for (int kind = 0; kind < 3; ++kind) said[kind] = words[0] + kExecFailureSaid[kind];
  return run_forked(
      [&](int) {
        if (env.empty()) execvp(argv[0], argv.data());
        else execvpe(argv[0], argv.data(), envp.data());
        const int kind = exec_failure(errno);
        [[maybe_unused]] const ssize_t written = write(2, said[kind].data(), said[kind].size());  // nothing to do if it fails
        return kExecFailureStatus[kind];
      },
      limits);
}

SubprocessResult run_subprocess(const std::string& shell_command, const SubprocessLimits& limits) {
  // Only words: the program itself, without a shell in between (as sh would have run
  // it; PATH searched as sh searches it, so sh keeps the case of no PATH at all).
  if (auto words = simple_command_words(shell_command))
    if (words->front().find('/') != std::string::npos || std::getenv("PATH")) return run_program(*words, limits);
  return run_shell_command(shell_command, limits);
}

}  // namespace lepp::audit
