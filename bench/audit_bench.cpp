// SPDX-License-Identifier: GPL-3.0-or-later
// The audit's own cost per run, apart from the program under audit
// (docs/BENCHMARKS.md, "Audit overhead"):
//   BM_AuditChecks      the rows on one finished run (certificate, angle with the
//                       exemption rule, Theorem 2, conformance replay of the trace)
//   BM_CommandAdapter   one --cmd run of a program that only copies a ready mesh:
//                       write the .poly, fork/exec /bin/sh, wait, read .node/.ele/.trace
//   BM_AuditLoop        run_audit per run with an engine that returns ready meshes
//                       (inputs, checks, bookkeeping; no shrinking, nothing fails)
//   BM_Diagnose         the catalogue's diagnosis of a point that is no choice on a
//                       whole replayed mesh (every terminal configuration), with the
//                       skip of far configurations (skip:1) and without (skip:0), the
//                       faces' facts kept (facts:1) and computed at every look (facts:0)
// Counters: vertices of the mesh checked; runs per iteration of the loop. Read CPU
// time (the program under audit runs in other processes; wall time includes them).
#include <benchmark/benchmark.h>

#include <stdlib.h>

#include <filesystem>
#include <map>

#include "lepp/audit/audit.h"
#include "lepp/engines/builtin_engines.h"
#include "lepp/audit/judge/checks.h"
#include "lepp/engines/command_engine.h"
#include "lepp/io.h"
#include "lepp/trace_io.h"
#include "problems.h"
#include "replay/replayer.h"  // audit/src: the replay's searches, white-box

namespace fs = std::filesystem;

namespace lepp::bench {
namespace {

struct Ready {
  std::string name;
  Pslg pslg;
  audit::EngineRun run;
  audit::EngineRequest request;
};

// The paper's problems at 30 degrees, refined once by the fast engine.
const std::vector<Ready>& ready_runs() {
  static const std::vector<Ready> runs = [] {
    std::vector<Ready> v;
    for (const Problem& p : paper_problems(std::string(LEPP_SOURCE_DIR) + "/corpus/paper", 30)) {
      Ready r;
      r.name = p.name;
      r.pslg = p.pslg;
      r.request.theta = 30;
      r.run = audit::fast_engine()(p.pslg, r.request);
      v.push_back(std::move(r));
    }
    return v;
  }();
  return runs;
}

void BM_AuditChecks(benchmark::State& state) {
  const Ready& r = ready_runs()[static_cast<std::size_t>(state.range(0))];
  for (auto _ : state) {
    audit::CaseResult c = audit::check_run(r.pslg, r.request, r.run, {});
    benchmark::DoNotOptimize(c);
  }
  state.counters["vertices"] = static_cast<double>(r.run.mesh.vertices.size());
  state.SetLabel(r.name);
}
BENCHMARK(BM_AuditChecks)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);

void BM_CommandAdapter(benchmark::State& state) {
  const Ready& r = ready_runs()[static_cast<std::size_t>(state.range(0))];
  std::string dir = (fs::temp_directory_path() / "lepp-audit-bench-XXXXXX").string();
  if (!mkdtemp(dir.data())) {
    state.SkipWithError("mkdtemp");
    return;
  }
  const std::string ready = dir + "/ready";
  write_mesh(ready, r.run.mesh);
  write_trace(ready + ".trace", *r.run.trace);
  audit::Engine engine = audit::command_engine("cp " + ready + ".node {out}.node && cp " + ready + ".ele {out}.ele && cp " +
                                               ready + ".trace {out}.trace # {in}");
  audit::EngineRequest req = r.request;
  req.work_dir = dir + "/work";
  fs::create_directories(req.work_dir);
  for (auto _ : state) {
    audit::EngineRun run = engine(r.pslg, req);
    if (run.status != audit::RunStatus::Ok) state.SkipWithError(run.detail.c_str());
    benchmark::DoNotOptimize(run);
  }
  state.counters["vertices"] = static_cast<double>(r.run.mesh.vertices.size());
  state.SetLabel(r.name);
  fs::remove_all(dir);
}
BENCHMARK(BM_CommandAdapter)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);

// Each paper problem's whole trace replayed, then points that are no choice asked
// about: every 50th step's point moved by a thousandth of its magnitude (unknown:
// the list of nearest rules) and by 64 ulps (within a thousand tolerances: precision).
void BM_Diagnose(benchmark::State& state) {
  const Ready& r = ready_runs()[static_cast<std::size_t>(state.range(0))];
  audit::ReplayRules rules;
  rules.min_angle_deg = r.request.theta;
  audit::replay_detail::Replayer replayer(r.pslg, rules);
  const std::vector<Point>& trace = *r.run.trace;
  for (const Point& p : trace) {
    audit::ReplayChoice c;
    if (!replayer.match(p, c)) {
      state.SkipWithError("the fast engine's trace is no choice");
      return;
    }
    replayer.insert(p, c);
  }
  std::vector<Point> probes;
  for (std::size_t i = 0; i < trace.size(); i += 50) {
    const Point p = trace[i];
    probes.push_back({p.x + 1e-3 * std::max(std::abs(p.x), std::abs(p.y)), p.y});
    double y = p.y;
    for (int k = 0; k < 64; ++k) y = std::nextafter(y, INFINITY);
    probes.push_back({p.x, y});
  }
  audit::replay_detail::Replayer::skip_far_terminals = state.range(1) != 0;
  audit::replay_detail::Replayer::cache_face_facts = state.range(2) != 0;
  for (auto _ : state)
    for (const Point& p : probes) benchmark::DoNotOptimize(replayer.diagnose(p));
  audit::replay_detail::Replayer::skip_far_terminals = true;
  audit::replay_detail::Replayer::cache_face_facts = true;
  state.counters["points"] = static_cast<double>(probes.size());
  state.counters["triangles"] = static_cast<double>(r.run.mesh.triangles.size());
  state.SetLabel(r.name);
}
BENCHMARK(BM_Diagnose)
    ->ArgsProduct({{0, 1, 2, 3}, {0, 1}, {0, 1}})
    ->ArgNames({"problem", "skip", "facts"})
    ->Unit(benchmark::kMillisecond);

// Generated inputs (seed 1, sizes 0 to 60): the loop's time per run when the engine costs nothing.
std::string fmt_key(const Pslg& p, double theta) {
  std::string k = std::to_string(theta) + "|";
  for (const Point& q : p.vertices) k += std::to_string(q.x) + "," + std::to_string(q.y) + ";";
  k += "|" + std::to_string(p.segments.size()) + "|" + std::to_string(p.holes.size());
  return k;
}

void BM_AuditLoop(benchmark::State& state) {
  std::map<std::string, audit::EngineRun> cache;
  audit::Engine fast = audit::fast_engine();
  audit::Engine cached = [&](const Pslg& p, const audit::EngineRequest& r) {
    std::string key = fmt_key(p, r.theta);
    auto it = cache.find(key);
    if (it == cache.end()) it = cache.emplace(key, fast(p, r)).first;
    audit::EngineRun run = it->second;
    run.seconds = 0;
    return run;
  };
  audit::AuditOptions o;
  o.thetas = {25};
  o.cases = static_cast<std::size_t>(state.range(0));
  o.inputs.paper = o.inputs.corpus = false;
  o.out_dir = (fs::temp_directory_path() / "lepp-audit-bench-out").string();
  audit::run_audit(cached, o);  // fills the cache
  std::size_t runs = 0;
  for (auto _ : state) runs += audit::run_audit(cached, o).cases;
  state.counters["runs"] = static_cast<double>(runs) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_AuditLoop)->Arg(60)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace lepp::bench

BENCHMARK_MAIN();
