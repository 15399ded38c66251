// SPDX-License-Identifier: GPL-3.0-or-later
// isolated_engine: an in-process engine that hangs, crashes, throws or eats
// memory ends as a RunStatus while the test process (the audit) goes on; a run
// that ends comes back bit for bit. Each misbehaving engine would hang, kill or
// throw through this test if the wrapper ran it in process.
#include <signal.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "lepp/audit/engine_run_bytes.h"
#include "lepp/audit/isolated_engine.h"

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
    sigaction(SIGCHLD, &before, nullptr);
    EXPECT_EQ(r.status, RunStatus::Ok) << (flags ? "SA_NOCLDWAIT: " : "SIG_IGN: ") << r.detail;
    EXPECT_LT(r.seconds, 10) << "the run waited for its timeout";
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
