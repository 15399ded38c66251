// SPDX-License-Identifier: GPL-3.0-or-later
// isolated_engine: an in-process engine that hangs, crashes, throws or eats
// memory ends as a RunStatus while the test process (the audit) goes on; a run
// that ends comes back bit for bit. Each misbehaving engine would hang, kill or
// throw through this test if the wrapper ran it in process.
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "lepp/audit/run/engine_run_bytes.h"
#include "lepp/audit/run/isolated_engine.h"
#include "lepp/audit/run/subprocess.h"

using namespace lepp;
using namespace lepp::audit;

namespace {

// Under AddressSanitizer (scripts/ci.d/10-sanitizers.sh) a SIGSEGV and a failed
// allocation are caught and reported by ASan, which then aborts (abort_on_error=1)
// or exits 1: still one contained failure of the child, with ASan's report.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAsan = true;
#else
constexpr bool kAsan = false;
#endif

bool asan_failure(const EngineRun& r) {
  return (r.status == RunStatus::Crashed || r.status == RunStatus::ExitCode) &&
         (r.detail + r.stderr_text).find("AddressSanitizer") != std::string::npos;
}

Pslg triangle() {
  Pslg p;
  p.vertices = {{0, 0}, {1, 0}, {0, 1}};
  p.segments = {{0, 1}, {1, 2}, {2, 0}};
  return p;
}

EngineRun run_isolated(Engine inner, double timeout = 5, std::size_t memory_mb = 0) {
  EngineRequest req;
  req.theta = 25;
  req.timeout_seconds = timeout;
  req.memory_mb = memory_mb;
  return isolated_engine(std::move(inner))(triangle(), req);
}

std::uint64_t bits(double d) {
  std::uint64_t b;
  std::memcpy(&b, &d, sizeof b);
  return b;
}

void expect_same_points(const std::vector<Point>& a, const std::vector<Point>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(bits(a[i].x), bits(b[i].x)) << "x of point " << i;
    EXPECT_EQ(bits(a[i].y), bits(b[i].y)) << "y of point " << i;
  }
}

// A run with every field set, the awkward doubles included.
EngineRun awkward_run() {
  EngineRun r;
  r.status = RunStatus::Stopped;
  const double subnormal = std::numeric_limits<double>::denorm_min() * 3;
  const double nan = std::nan("0x5a5a");  // a payload, kept as bits
  r.mesh.vertices = {{-0.0, 0.0}, {subnormal, -subnormal}, {1e300, -1e300}, {0.1, nan}, {4.2e-314, 7.5e-301}};
  r.mesh.input_vertices = 3;
  r.mesh.triangles = {{0, 1, 2}, {2, 3, 4}};
  r.mesh.constrained_edges = {{0, 1, 0}, {1, 2, -1}, {3, 4, 7}};
  r.trace = std::vector<Point>{{-0.0, subnormal}, {1e300, 1.0 / 3}};
  r.exit_code = -7;
  r.signal = 11;
  r.detail = std::string("a detail\nwith a newline and a \0 byte", 35);
  r.stderr_text = "warning: something";
  r.seconds = 1e300;
  r.output_files = {"/tmp/a.node", "", "/tmp/b c.ele"};
  return r;
}

void expect_same_run(const EngineRun& want, const EngineRun& got, bool compare_seconds) {
  EXPECT_EQ(got.status, want.status);
  expect_same_points(want.mesh.vertices, got.mesh.vertices);
  EXPECT_EQ(got.mesh.input_vertices, want.mesh.input_vertices);
  EXPECT_EQ(got.mesh.triangles, want.mesh.triangles);
  ASSERT_EQ(got.mesh.constrained_edges.size(), want.mesh.constrained_edges.size());
  for (std::size_t i = 0; i < want.mesh.constrained_edges.size(); ++i) {
    EXPECT_EQ(got.mesh.constrained_edges[i].a, want.mesh.constrained_edges[i].a);
    EXPECT_EQ(got.mesh.constrained_edges[i].b, want.mesh.constrained_edges[i].b);
    EXPECT_EQ(got.mesh.constrained_edges[i].segment, want.mesh.constrained_edges[i].segment);
  }
  ASSERT_EQ(got.trace.has_value(), want.trace.has_value());
  if (want.trace) expect_same_points(*want.trace, *got.trace);
  EXPECT_EQ(got.exit_code, want.exit_code);
  EXPECT_EQ(got.signal, want.signal);
  EXPECT_EQ(got.detail, want.detail);
  EXPECT_EQ(got.stderr_text, want.stderr_text);
  EXPECT_EQ(got.output_files, want.output_files);
  if (compare_seconds) EXPECT_EQ(bits(got.seconds), bits(want.seconds));
}

TEST(IsolatedEngine, HangIsKilledAtTheTimeout) {
  // In process this never returns (ctest's timeout would fail the test).
  EngineRun r = run_isolated(
      [](const Pslg&, const EngineRequest&) -> EngineRun {
        for (;;) pause();
      },
      1);
  EXPECT_EQ(r.status, RunStatus::TimedOut) << r.detail;
  EXPECT_NE(r.detail.find("killed after"), std::string::npos) << r.detail;
}

TEST(IsolatedEngine, SegfaultIsACrashWithItsSignal) {
  EngineRun r = run_isolated([](const Pslg&, const EngineRequest&) -> EngineRun {
    raise(SIGSEGV);
    return {};
  });
  if (kAsan) {
    EXPECT_TRUE(asan_failure(r)) << r.detail << r.stderr_text;
    return;
  }
  EXPECT_EQ(r.status, RunStatus::Crashed);
  EXPECT_EQ(r.signal, SIGSEGV) << r.detail;
}

TEST(IsolatedEngine, AbortIsACrashWithItsSignalAndMessage) {
  EngineRun r = run_isolated([](const Pslg&, const EngineRequest&) -> EngineRun {
    std::fputs("CGAL ERROR: assertion violation!\n", stderr);
    std::abort();
  });
  EXPECT_EQ(r.status, RunStatus::Crashed);
  EXPECT_EQ(r.signal, SIGABRT) << r.detail;
  EXPECT_NE(r.detail.find("assertion violation"), std::string::npos) << r.detail;
  EXPECT_NE(r.stderr_text.find("assertion violation"), std::string::npos);
}

TEST(IsolatedEngine, ExceptionIsACrashWithItsMessage) {
  EngineRun r = run_isolated([](const Pslg&, const EngineRequest&) -> EngineRun { throw std::runtime_error("no luck"); });
  EXPECT_EQ(r.status, RunStatus::Crashed);
  EXPECT_EQ(r.signal, 0);
  EXPECT_NE(r.detail.find("no luck"), std::string::npos) << r.detail;
}

TEST(IsolatedEngine, ExitInTheEngineIsAnExitCode) {
  EngineRun r = run_isolated([](const Pslg&, const EngineRequest&) -> EngineRun { std::_Exit(3); });
  EXPECT_EQ(r.status, RunStatus::ExitCode);
  EXPECT_EQ(r.exit_code, 3);
  EngineRun zero = run_isolated([](const Pslg&, const EngineRequest&) -> EngineRun { std::_Exit(0); });
  EXPECT_EQ(zero.status, RunStatus::UnreadableOutput) << zero.detail;
  EXPECT_TRUE(zero.mesh.vertices.empty());
}

char* volatile escaped = nullptr;

TEST(IsolatedEngine, MemoryHogFailsInTheChild) {
  // 4 GB reserved and touched at both ends under a 64 MB cap: the allocation fails
  // in the child. In process (no cap) it succeeds and the run would be Ok.
  EngineRun r = run_isolated(
      [](const Pslg&, const EngineRequest&) -> EngineRun {
        const std::size_t n = std::size_t{4} << 30;
        std::unique_ptr<char[]> hog(new char[n]);
        hog[0] = hog[n - 1] = 1;
        escaped = hog.get();  // so the compiler cannot drop the allocation
        return EngineRun{};
      },
      5, 64);
  if (kAsan) {
    EXPECT_TRUE(asan_failure(r)) << r.detail << r.stderr_text;
    return;
  }
  EXPECT_EQ(r.status, RunStatus::Crashed) << r.detail;
  EXPECT_NE(r.detail.find("bad_alloc"), std::string::npos) << r.detail;
}

TEST(IsolatedEngine, MemoryCapLeavesRoomForAnOrdinaryRun) {
  EngineRun r = run_isolated([](const Pslg&, const EngineRequest&) { return EngineRun{}; }, 5, 64);
  EXPECT_EQ(r.status, RunStatus::Ok) << r.detail << r.stderr_text;
}

// A process started with SIGCHLD ignored (the disposition survives exec; some
// launchers and CI runners leave it so): the kernel reaps the children itself, and a
// wait loop that only trusts waitpid would see every run last until its timeout.
TEST(IsolatedEngine, ARunEndsWhenTheAuditWasStartedWithSigchldIgnored) {
  for (int flags : {0, SA_NOCLDWAIT}) {
    struct sigaction ignore {}, before {};
    ignore.sa_handler = flags ? SIG_DFL : SIG_IGN;
    ignore.sa_flags = flags;
    sigemptyset(&ignore.sa_mask);
    ASSERT_EQ(sigaction(SIGCHLD, &ignore, &before), 0);
    EngineRun r = run_isolated([](const Pslg&, const EngineRequest&) { return EngineRun{}; }, 20);
    // And a program (the --cmd adapter's way).
    SubprocessLimits limits;
    limits.timeout_seconds = 20;
    const SubprocessResult sr = run_subprocess("exit 3", limits);
    sigaction(SIGCHLD, &before, nullptr);
    EXPECT_EQ(r.status, RunStatus::Ok) << (flags ? "SA_NOCLDWAIT: " : "SIG_IGN: ") << r.detail;
    EXPECT_LT(r.seconds, 10) << "the run waited for its timeout";
    EXPECT_EQ(sr.exit_code, 3) << sr.detail;
    EXPECT_FALSE(sr.timed_out);
  }
}

int global_touched = 0;

TEST(IsolatedEngine, RunsInAnotherProcess) {
  const pid_t parent = getpid();
  EngineRun r = run_isolated([](const Pslg&, const EngineRequest&) {
    global_touched = 1;
    EngineRun run;
    run.detail = std::to_string(getpid());
    return run;
  });
  ASSERT_EQ(r.status, RunStatus::Ok) << r.detail;
  EXPECT_NE(r.detail, std::to_string(parent));
  EXPECT_EQ(global_touched, 0);
}

TEST(IsolatedEngine, RunComesBackBitForBit) {
  const EngineRun want = awkward_run();
  EngineRun r = run_isolated([&want](const Pslg& p, const EngineRequest& q) {
    EngineRun run = want;
    if (p.vertices.size() != 3 || q.theta != 25) run.detail = "the input or the request did not reach the child";
    return run;
  });
  expect_same_run(want, r, false);
  // Seconds are the parent's clock, not the child's 1e300.
  EXPECT_GT(r.seconds, 0);
  EXPECT_LT(r.seconds, 60);
}

TEST(IsolatedEngine, ALargeMeshComesBackWhole) {
  // Several MB: more than a pipe holds, read while the child writes.
  EngineRun want;
  for (int i = 0; i < 300000; ++i) want.mesh.vertices.push_back({i * 0.5, -i / 3.0});
  for (int i = 0; i + 2 < 300000; i += 3) want.mesh.triangles.push_back({i, i + 1, i + 2});
  want.mesh.input_vertices = 3;
  EngineRun r = run_isolated([&want](const Pslg&, const EngineRequest&) { return want; });
  expect_same_run(want, r, false);
}

// The hazard the fork server removes (fork_server.h): a child forked from a
// threaded audit inherits every lock another thread holds at that moment, held
// forever. Here another thread holds, through the whole run, a lock the engine
// takes: a child forked from this process waits on it until its timeout; a child
// of the server, forked from a copy made before the lock was taken, does not.
std::mutex g_lock_the_engine_takes;

TEST(IsolatedEngine, ALockHeldByAnotherThreadAtTheForkDoesNotHangTheRun) {
  Engine isolated = isolated_engine([](const Pslg&, const EngineRequest&) {
    std::lock_guard<std::mutex> lock(g_lock_the_engine_takes);
    return EngineRun{};
  });
  std::mutex m;
  std::condition_variable cv;
  bool held = false, done = false;
  std::thread holder([&] {
    std::lock_guard<std::mutex> lock(g_lock_the_engine_takes);
    std::unique_lock<std::mutex> lk(m);
    held = true;
    cv.notify_all();
    cv.wait(lk, [&] { return done; });
  });
  {
    std::unique_lock<std::mutex> lk(m);
    cv.wait(lk, [&] { return held; });
  }
  EngineRequest req;
  req.timeout_seconds = 10;
  const EngineRun r = isolated(triangle(), req);
  {
    std::lock_guard<std::mutex> lk(m);
    done = true;
  }
  cv.notify_all();
  holder.join();
  EXPECT_EQ(r.status, RunStatus::Ok) << r.detail;
}

// The fork server killed while a run is on: that run ends (Crashed, saying the
// server ended, never a wait for a status that cannot come), and every later run
// of the engine is Crashed at once (the server is gone), not a hang.
TEST(IsolatedEngine, AKilledForkServerEndsItsRunsNotTheAudit) {
  Engine isolated = isolated_engine([](const Pslg&, const EngineRequest&) {
    kill(getppid(), SIGKILL);  // the child's parent is the server
    usleep(100000);
    return EngineRun{};
  });
  EngineRequest req;
  req.timeout_seconds = 20;
  const EngineRun during = isolated(triangle(), req);
  EXPECT_EQ(during.status, RunStatus::Crashed);
  EXPECT_NE(during.detail.find("fork server ended during the run"), std::string::npos) << during.detail;
  EXPECT_LT(during.seconds, 10);
  const EngineRun after = isolated(triangle(), req);
  EXPECT_EQ(after.status, RunStatus::Crashed);
  EXPECT_NE(after.detail.find("fork server is gone"), std::string::npos) << after.detail;
}

// Two isolated engines (lepp audit's engine and its comparison), the first
// destroyed first: its server ends although the second server, forked later,
// holds a copy of its socket.
TEST(IsolatedEngine, AnEngineDestroyedBeforeALaterOneEndsItsServer) {
  auto first = std::make_unique<Engine>(isolated_engine([](const Pslg&, const EngineRequest&) { return EngineRun{}; }));
  Engine second = isolated_engine([](const Pslg&, const EngineRequest&) { return EngineRun{}; });
  EngineRequest req;
  EXPECT_EQ((*first)(triangle(), req).status, RunStatus::Ok);
  const auto t0 = std::chrono::steady_clock::now();
  std::thread destroy([&] { first.reset(); });
  destroy.join();  // waited for forever if the destructor waited for the server to leave by itself
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 10);
  EXPECT_EQ(second(triangle(), req).status, RunStatus::Ok);
}

// Runs from several threads at once through one server: each comes back with
// its own input's answer, whatever the order the children end in.
TEST(IsolatedEngine, ConcurrentRunsEachGetTheirOwnAnswer) {
  Engine isolated = isolated_engine([](const Pslg& p, const EngineRequest& q) {
    usleep(static_cast<useconds_t>((p.vertices.size() * 7919) % 3000));  // end out of order
    EngineRun run;
    run.detail = std::to_string(p.vertices.size()) + " " + std::to_string(q.theta);
    if (p.vertices.size() % 5 == 0) std::abort();  // and some die
    return run;
  });
  constexpr int kThreads = 4, kRuns = 40;
  std::vector<std::string> wrong(kThreads);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      for (int i = 0; i < kRuns; ++i) {
        Pslg p;
        const std::size_t n = 3 + static_cast<std::size_t>(t * kRuns + i);
        for (std::size_t k = 0; k < n; ++k) p.vertices.push_back({static_cast<double>(k), 0.5 * k});
        EngineRequest req;
        req.theta = 20 + t;
        req.timeout_seconds = 20;
        const EngineRun r = isolated(p, req);
        const bool dies = n % 5 == 0;
        const std::string want = std::to_string(n) + " " + std::to_string(req.theta);
        if (dies ? r.status != RunStatus::Crashed || r.signal != SIGABRT : r.status != RunStatus::Ok || r.detail != want)
          wrong[t] += "n=" + std::to_string(n) + ": " + to_string(r.status) + " " + r.detail + "; ";
      }
    });
  for (std::thread& th : threads) th.join();
  for (const std::string& w : wrong) EXPECT_EQ(w, "");
}

// The call crosses to the server whole: every field of the PSLG and the request.
TEST(EngineRunBytes, ACallRoundTripsAndEveryPrefixIsRefused) {
  Pslg p;
  p.vertices = {{-0.0, std::numeric_limits<double>::denorm_min()}, {1e300, 0.1}, {2, 3}};
  p.vertex_markers = {1, 0, -7};
  p.segments = {{0, 1, 5}, {1, 2, -2}};
  p.holes = {{0.25, 0.5}};
  p.regions = {{{0.1, 0.2}, 3.5, 0.01}};
  p.source = "a.poly";
  p.vertex_lines = {2, 3, 4};
  p.segment_lines = {6, 7};
  p.hole_lines = {9};
  p.region_lines = {11};
  p.segment_origin = {0, 0};
  p.crossing_vertices = 1;
  EngineRequest q;
  q.method = Method::Midpoint;
  q.theta = 27.5;
  q.timeout_seconds = 0.25;
  q.memory_mb = 123;
  q.work_dir = "/tmp/w";
  const std::string bytes = encode_engine_call(p, q);
  Pslg p2;
  EngineRequest q2;
  decode_engine_call(bytes, p2, q2);
  expect_same_points(p.vertices, p2.vertices);
  expect_same_points(p.holes, p2.holes);
  EXPECT_EQ(p2.vertex_markers, p.vertex_markers);
  ASSERT_EQ(p2.segments.size(), 2u);
  EXPECT_EQ(p2.segments[1].a, 1);
  EXPECT_EQ(p2.segments[1].b, 2);
  EXPECT_EQ(p2.segments[1].marker, -2);
  ASSERT_EQ(p2.regions.size(), 1u);
  EXPECT_EQ(p2.regions[0].at, p.regions[0].at);
  EXPECT_EQ(p2.regions[0].attribute, 3.5);
  EXPECT_EQ(p2.regions[0].max_area, 0.01);
  EXPECT_EQ(p2.source, p.source);
  EXPECT_EQ(p2.vertex_lines, p.vertex_lines);
  EXPECT_EQ(p2.segment_lines, p.segment_lines);
  EXPECT_EQ(p2.hole_lines, p.hole_lines);
  EXPECT_EQ(p2.region_lines, p.region_lines);
  EXPECT_EQ(p2.segment_origin, p.segment_origin);
  EXPECT_EQ(p2.crossing_vertices, 1u);
  EXPECT_EQ(q2.method, Method::Midpoint);
  EXPECT_EQ(q2.theta, 27.5);
  EXPECT_EQ(q2.timeout_seconds, 0.25);
  EXPECT_EQ(q2.memory_mb, 123u);
  EXPECT_EQ(q2.work_dir, "/tmp/w");
  for (std::size_t n = 0; n < bytes.size(); ++n)
    EXPECT_THROW(decode_engine_call(bytes.substr(0, n), p2, q2), std::runtime_error) << "prefix of " << n << " bytes";
  EXPECT_THROW(decode_engine_call(bytes + "x", p2, q2), std::runtime_error);
}

TEST(EngineRunBytes, RoundTripIsExact) {
  const EngineRun want = awkward_run();
  expect_same_run(want, decode_engine_run(encode_engine_run(want)), true);
  EngineRun no_trace;
  EngineRun back = decode_engine_run(encode_engine_run(no_trace));
  EXPECT_FALSE(back.trace.has_value());
}

TEST(EngineRunBytes, EveryPrefixIsRefused) {
  // A child that dies mid-write leaves a prefix: none reads as a (shorter) run.
  const std::string whole = encode_engine_run(awkward_run());
  for (std::size_t n = 0; n < whole.size(); ++n)
    EXPECT_THROW(decode_engine_run(whole.substr(0, n)), std::runtime_error) << "prefix of " << n << " bytes";
  EXPECT_THROW(decode_engine_run(whole + "x"), std::runtime_error);
}

TEST(EngineRunBytes, ACorruptedCountOrStatusIsRefused) {
  std::string bytes = encode_engine_run(awkward_run());
  std::string bad_status = bytes;
  bad_status[8] = 99;  // the status, right after the begin mark
  EXPECT_THROW(decode_engine_run(bad_status), std::runtime_error);
  std::string bad_mark = bytes;
  bad_mark[bad_mark.size() - 1] ^= 1;
  EXPECT_THROW(decode_engine_run(bad_mark), std::runtime_error);
  std::string huge_count = bytes;
  // The detail's length (after mark, 3 int32 and a double): claims more bytes than there are.
  huge_count[8 + 12 + 8 + 7] = 0x7f;
  EXPECT_THROW(decode_engine_run(huge_count), std::runtime_error);
}

}  // namespace
