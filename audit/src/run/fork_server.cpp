// SPDX-License-Identifier: GPL-3.0-or-later
// The fork server: one process forked before the threads, forking a child per isolated run.
#include "fork_server.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/signalfd.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "child_process.h"
#include "lepp/audit/run/engine_run_bytes.h"

namespace lepp::audit {
namespace {

using Clock = std::chrono::steady_clock;

constexpr char kMagic[8] = {'L', 'E', 'P', 'P', 'F', 'O', 'R', 'K'};

// A request: this header, with the run's three pipe ends (stderr, result, end
// status) as SCM_RIGHTS, then `bytes` of encode_engine_call.
struct Header {
  char magic[8];
  std::uint64_t bytes;
};

bool write_all(int fd, const char* p, std::size_t n) {
  while (n > 0) {
    ssize_t k = send(fd, p, n, MSG_NOSIGNAL);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    p += k;
    n -= static_cast<std::size_t>(k);
  }
  return true;
}

bool write_pipe(int fd, const void* p, std::size_t n) {
  for (;;) {
    ssize_t k = write(fd, p, n);
    if (k < 0 && errno == EINTR) continue;
    return k == static_cast<ssize_t>(n);  // a few bytes into a pipe: written whole or not at all
  }
}

bool read_all(int fd, char* p, std::size_t n) {
  while (n > 0) {
    ssize_t k = read(fd, p, n);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    p += k;
    n -= static_cast<std::size_t>(k);
  }
  return true;
}

// A header and room for the three descriptors, as sendmsg and recvmsg take them.
struct HeaderMessage {
  explicit HeaderMessage(Header& h) : iov{&h, sizeof h} {
    msg.msg_iov = &iov;
    msg.msg_iovlen = 1;
    msg.msg_control = cbuf;
    msg.msg_controllen = sizeof cbuf;
  }
  HeaderMessage(const HeaderMessage&) = delete;
  HeaderMessage& operator=(const HeaderMessage&) = delete;
  struct iovec iov;
  alignas(struct cmsghdr) char cbuf[CMSG_SPACE(3 * sizeof(int))] = {};
  struct msghdr msg{};
};

bool send_request(int control, const std::string& payload, const int fds[3]) {
  Header h{};
  std::memcpy(h.magic, kMagic, 8);
  h.bytes = payload.size();
  HeaderMessage m(h);
  struct msghdr& msg = m.msg;
  struct cmsghdr* c = CMSG_FIRSTHDR(&msg);
  c->cmsg_level = SOL_SOCKET;
  c->cmsg_type = SCM_RIGHTS;
  c->cmsg_len = CMSG_LEN(3 * sizeof(int));
  std::memcpy(CMSG_DATA(c), fds, 3 * sizeof(int));
  ssize_t n;
  do n = sendmsg(control, &msg, MSG_NOSIGNAL);
  while (n < 0 && errno == EINTR);
  if (n < 0) return false;
  // The descriptors went with the first bytes; the rest of the header, then the call.
  return write_all(control, reinterpret_cast<const char*>(&h) + n, sizeof h - static_cast<std::size_t>(n)) &&
         write_all(control, payload.data(), payload.size());
}

// In the server: one request, or false when the socket has ended (or speaks nonsense).
bool receive_request(int control, std::string& payload, int fds[3]) {
  Header h{};
  HeaderMessage m(h);
  struct msghdr& msg = m.msg;
  ssize_t n;
  do n = recvmsg(control, &msg, MSG_CMSG_CLOEXEC);
  while (n < 0 && errno == EINTR);
  if (n <= 0) return false;
  struct cmsghdr* c = CMSG_FIRSTHDR(&msg);
  if (!c || c->cmsg_type != SCM_RIGHTS || c->cmsg_len != CMSG_LEN(3 * sizeof(int))) return false;
  std::memcpy(fds, CMSG_DATA(c), 3 * sizeof(int));
  if (!read_all(control, reinterpret_cast<char*>(&h) + n, sizeof h - static_cast<std::size_t>(n)) ||
      std::memcmp(h.magic, kMagic, 8) != 0) {
    for (int i = 0; i < 3; ++i) close(fds[i]);
    return false;
  }
  payload.resize(h.bytes);
  if (!read_all(control, payload.data(), payload.size())) {
    for (int i = 0; i < 3; ++i) close(fds[i]);
    return false;
  }
  return true;
}

// The server's life: requests in, children out, each child's end reported.
[[noreturn]] void serve(int control, const ForkServer::Body& body) {
  signal(SIGINT, SIG_IGN);  // a Ctrl-C is the audit's to handle; the server ends with its socket
  // Nothing of the audit's terminal or pipes: whoever waits for the audit's output
  // (a shell's $(...), ctest) must not wait for a server that outlives it.
  const int devnull = open("/dev/null", O_RDWR);
  if (devnull >= 0) {
    for (int fd = 0; fd <= 2; ++fd) dup2(devnull, fd);
    if (devnull > 2) close(devnull);
  }
  signal(SIGPIPE, SIG_IGN);
  sigset_t chld;
  sigemptyset(&chld);
  sigaddset(&chld, SIGCHLD);
  signal(SIGCHLD, SIG_DFL);
  sigprocmask(SIG_BLOCK, &chld, nullptr);
  const int ended = signalfd(-1, &chld, SFD_CLOEXEC | SFD_NONBLOCK);
  if (ended < 0) _exit(1);
  std::map<pid_t, int> status_of;  // running children: where their end goes
  for (;;) {
    struct pollfd p[2] = {{control, POLLIN, 0}, {ended, POLLIN, 0}};
    if (poll(p, 2, -1) < 0 && errno != EINTR) _exit(1);
    if (p[1].revents) {
      struct signalfd_siginfo si;
      while (read(ended, &si, sizeof si) > 0) {
      }
      int wstatus;
      for (pid_t w; (w = waitpid(-1, &wstatus, WNOHANG)) > 0;) {
        auto it = status_of.find(w);
        if (it == status_of.end()) continue;
        write_pipe(it->second, &wstatus, sizeof wstatus);
        close(it->second);
        status_of.erase(it);
      }
    }
    if (!p[0].revents) continue;
    std::string payload;
    int fds[3];
    if (!receive_request(control, payload, fds)) _exit(0);  // our parent is done, or gone
    const pid_t w = fork();
    if (w == 0) {
      // The child says it started, before anything of the body runs: a body that
      // kills the server at once must not leave the client without the child's pid.
      setpgid(0, 0);  // its group first: the client kills the group it is told of
      const std::int64_t started = getpid();
      write_pipe(fds[2], &started, sizeof started);
      close(control);
      close(ended);
      close(fds[2]);
      for (const auto& [pid, fd] : status_of) close(fd);
      sigprocmask(SIG_UNBLOCK, &chld, nullptr);
      set_up_child(fds[0], SubprocessLimits{0, 0, 0, {}});
      Pslg pslg;
      EngineRequest req;
      try {
        decode_engine_call(payload, pslg, req);
      } catch (const std::exception& e) {
        dprintf(2, "fork server: %s\n", e.what());
        _exit(125);
      }
      int status = 125;
      try {
        status = body(pslg, req, fds[1]);
      } catch (...) {
      }
      _exit(status);
    }
    close(fds[0]);
    close(fds[1]);
    if (w > 0) setpgid(w, w);  // its own group before anyone may kill it (the child does the same)
    if (w > 0) {
      status_of[w] = fds[2];  // the child wrote its pid there; its end follows
    } else {
      const std::int64_t reply = -static_cast<std::int64_t>(errno);
      write_pipe(fds[2], &reply, sizeof reply);
      close(fds[2]);
    }
  }
}

// The child's end as the server reports it on the status pipe.
class ReportedEnd : public ChildEnd {
 public:
  explicit ReportedEnd(int fd) : fd_(fd) {}
  int poll(int* wstatus, std::string* detail) override {
    ssize_t k;
    do k = read(fd_, wstatus, sizeof *wstatus);
    while (k < 0 && errno == EINTR);
    if (k == static_cast<ssize_t>(sizeof *wstatus)) return 1;
    if (k < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return 0;
    *detail = "the fork server ended during the run: the child's exit status is lost";
    return -1;
  }
  void wait(int* wstatus) override {
    struct pollfd p{fd_, POLLIN, 0};
    std::string ignored;
    while (::poll(&p, 1, -1) < 0 && errno == EINTR) {
    }
    poll(wstatus, &ignored);
  }

 private:
  int fd_;
};

void close_all(std::initializer_list<int> fds) {
  for (int fd : fds) close(fd);
}

}  // namespace

ForkServer::ForkServer(Body body) {
  int sv[2];
  if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0)
    throw std::runtime_error(std::string("fork server: socketpair: ") + std::strerror(errno));
  const pid_t pid = fork();
  if (pid < 0) {
    close_all({sv[0], sv[1]});
    throw std::runtime_error(std::string("fork server: fork: ") + std::strerror(errno));
  }
  if (pid == 0) {
    close(sv[0]);
    serve(sv[1], body);
  }
  close(sv[1]);
  control_ = sv[0];
  server_ = pid;
}

ForkServer::~ForkServer() {
  // No run is left (each holds the server). The server would leave at the end of its
  // socket, but a server made later holds a copy of our end (it was forked with it),
  // so it is killed rather than waited for.
  close(control_);
  kill(server_, SIGKILL);
  int wstatus;
  while (waitpid(server_, &wstatus, 0) < 0 && errno == EINTR) {
  }
}

SubprocessResult ForkServer::run(const Pslg& pslg, const EngineRequest& req, const SubprocessLimits& limits) {
  SubprocessResult r;
  int err[2], res[2], status[2];
  if (pipe2(err, O_CLOEXEC) != 0 || pipe2(res, O_CLOEXEC) != 0 || pipe2(status, O_CLOEXEC) != 0) {
    r.detail = std::string("pipe: ") + std::strerror(errno);
    return r;  // (a descriptor or two lost, on a process out of them)
  }
  const std::string payload = encode_engine_call(pslg, req);
  const auto t0 = Clock::now();
  bool sent;
  {
    std::lock_guard<std::mutex> lock(send_);
    const int ends[3] = {err[1], res[1], status[1]};
    sent = send_request(control_, payload, ends);
  }
  close_all({err[1], res[1], status[1]});
  std::int64_t reply = 0;
  if (!sent || !read_all(status[0], reinterpret_cast<char*>(&reply), sizeof reply) || reply <= 0) {
    r.detail = !sent || reply == 0 ? std::string("the fork server is gone")
                                   : std::string("fork: ") + std::strerror(static_cast<int>(-reply));
    close_all({err[0], res[0], status[0]});
    return r;
  }
  r.started = true;
  fcntl(status[0], F_SETFL, O_NONBLOCK);
  ReportedEnd end(status[0]);
  wait_for_child(static_cast<pid_t>(reply), err[0], res[0], limits, t0, end, r);
  close(status[0]);
  return r;
}

}  // namespace lepp::audit
