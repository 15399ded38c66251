// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind triangle_wasm.h: Shewchuk's Triangle, the triangle-wasm build run
// under node by tools/triangle/triangle.js.
#include "triangle_wasm.h"

#include "shell_command.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <fmt/format.h>

namespace lepp::others {
bool triangle_available(const std::string& root) {
  std::string out;
  return run_shell("node --version >/dev/null 2>&1 && test -f " +
                   shell_quote(root + "/tools/triangle/node_modules/triangle-wasm/package.json"),
               out) == 0;
}

std::string triangle_command(const std::string& root, const std::string& poly, double theta, std::int64_t budget,
                             const std::string& prefix) {
  std::string switches = fmt::format("-pq{}", theta);
  if (budget > 0) switches += fmt::format("S{}", budget);
  return fmt::format("node {} {} {} {}", shell_quote(root + "/tools/triangle/triangle.js"), shell_quote(poly), switches, shell_quote(prefix));
}

TriangleRun run_triangle(const std::string& root, const std::string& poly, double theta, std::int64_t budget,
                         const std::string& prefix) {
  TriangleRun r;
  auto t0 = std::chrono::steady_clock::now();
  r.status = run_shell(triangle_command(root, poly, theta, budget, prefix) + " 2>&1", r.output);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  long long added = -1;
  if (r.status == 0 && std::sscanf(r.output.c_str(), "points added %lld", &added) == 1) r.points_added = added;
  return r;
}

namespace {

// A JSON string (the server reads each case as a JSON array).
std::string json_string(const std::string& s) {
  std::string q = "\"";
  for (unsigned char c : s) {
    if (c == '"' || c == '\\') q += '\\', q += static_cast<char>(c);
    else if (c < 0x20) q += fmt::format("\\u{:04x}", c);
    else q += static_cast<char>(c);
  }
  return q + "\"";
}

// write() all of it without dying of SIGPIPE if node is gone: SIGPIPE is blocked
// in this thread for the call and a pending one consumed.
bool write_all(int fd, const std::string& data) {
  sigset_t pipe_set, old;
  sigemptyset(&pipe_set);
  sigaddset(&pipe_set, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipe_set, &old);
  bool ok = true;
  for (std::size_t at = 0; at < data.size();) {
    ssize_t n = write(fd, data.data() + at, data.size() - at);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      ok = false;
      break;
    }
    at += static_cast<std::size_t>(n);
  }
  if (!ok) {
    struct timespec zero = {0, 0};
    sigtimedwait(&pipe_set, nullptr, &zero);
  }
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
  return ok;
}

}  // namespace

TriangleServer::TriangleServer(std::string root) : root_(std::move(root)) {}

TriangleServer::~TriangleServer() { stop(); }

bool TriangleServer::start(std::string& why) {
  int in[2], out[2];
  if (pipe2(in, O_CLOEXEC) != 0) {
    why = std::string("pipe: ") + std::strerror(errno);
    return false;
  }
  if (pipe2(out, O_CLOEXEC) != 0) {
    why = std::string("pipe: ") + std::strerror(errno);
    close(in[0]);
    close(in[1]);
    return false;
  }
  const std::string script = root_ + "/tools/triangle/triangle.js";
  pid_t pid = fork();
  if (pid < 0) {
    why = std::string("fork: ") + std::strerror(errno);
    for (int fd : {in[0], in[1], out[0], out[1]}) close(fd);
    return false;
  }
  if (pid == 0) {
    // Only async-signal-safe calls between fork and exec.
    dup2(in[0], 0);
    dup2(out[1], 1);
    int devnull = open("/dev/null", O_WRONLY);
    if (devnull >= 0) dup2(devnull, 2);
    signal(SIGPIPE, SIG_DFL);
    execlp("node", "node", script.c_str(), "--serve", static_cast<char*>(nullptr));
    _exit(127);
  }
  close(in[0]);
  close(out[1]);
  pid_ = pid;
  to_node_ = in[1];
  from_node_ = out[0];
  fcntl(from_node_, F_SETFL, O_NONBLOCK);
  pending_.clear();
  ++starts_;
  return true;
}

void TriangleServer::stop() {
  if (pid_ < 0) return;
  close(to_node_);  // end of its stdin: node exits by itself
  close(from_node_);
  // Give it a moment, then make sure.
  for (int i = 0; i < 20; ++i) {
    if (waitpid(pid_, nullptr, WNOHANG) == pid_) {
      pid_ = -1;
      return;
    }
    usleep(1000);
  }
  kill(pid_, SIGKILL);
  waitpid(pid_, nullptr, 0);
  pid_ = -1;
}

TriangleRun TriangleServer::run(const std::string& poly, double theta, std::int64_t budget, const std::string& prefix,
                                double timeout_seconds) {
  TriangleRun r;
  std::string why;
  if (pid_ < 0 && !start(why)) {
    r.output = why;
    return r;
  }
  // The case's clock starts now: node's start and the wasm's load are not the case's time.
  const auto t0 = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  std::string switches = fmt::format("-pq{}", theta);
  if (budget > 0) switches += fmt::format("S{}", budget);
  if (!write_all(to_node_, "[" + json_string(poly) + "," + json_string(switches) + "," + json_string(prefix) + "]\n")) {
    stop();
    r.output = "the Triangle server is gone";
    return r;
  }
  // The answer: one line.
  for (;;) {
    const std::size_t nl = pending_.find('\n');
    if (nl != std::string::npos) {
      const std::string line = pending_.substr(0, nl);
      pending_.erase(0, nl + 1);
      int status = -1;
      long long added = -1;
      int used = 0;
      if (std::sscanf(line.c_str(), "%d %lld %n", &status, &added, &used) >= 2) {
        r.status = status;
        r.points_added = status == 0 ? added : -1;
        r.output = line.substr(static_cast<std::size_t>(used));
      } else {
        r.output = "unreadable answer from the Triangle server: " + line;
        stop();
      }
      r.seconds = elapsed();
      return r;
    }
    const double left = timeout_seconds > 0 ? timeout_seconds - elapsed() : 1e9;
    if (left <= 0) {
      stop();
      r.output = fmt::format("killed after {:.3g} s", timeout_seconds);
      r.seconds = elapsed();
      return r;
    }
    struct pollfd p = {from_node_, POLLIN, 0};
    const int ready = poll(&p, 1, static_cast<int>(std::min(left * 1000 + 1, 1000.0)));
    if (ready < 0 && errno != EINTR) break;
    if (ready <= 0) continue;
    char buf[4096];
    const ssize_t n = read(from_node_, buf, sizeof buf);
    if (n > 0) pending_.append(buf, static_cast<std::size_t>(n));
    else if (n == 0 || (errno != EAGAIN && errno != EINTR)) break;
  }
  stop();
  r.output = "the Triangle server died";
  r.seconds = elapsed();
  return r;
}

}  // namespace lepp::others
