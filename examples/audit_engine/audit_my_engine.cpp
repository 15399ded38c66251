// SPDX-License-Identifier: GPL-3.0-or-later
// Audits a C++ mesher, each run in a child process, against the paper's statements with
// lepp::audit. "My engine" here is lepp's fast engine called by hand, to show
// what an engine fills in; put your own mesher in its place. Prints the
// markdown report; exit 0 when every row holds, 1 otherwise.
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "lepp/audit/audit.h"
#include "lepp/audit/run/isolated_engine.h"
#include "lepp/audit/report/report.h"
#include "lepp/fast.h"

lepp::audit::EngineRun my_engine(const lepp::Pslg& pslg, const lepp::audit::EngineRequest& request) {
  lepp::audit::EngineRun run;
  lepp::RefineOptions options;
  options.min_angle_deg = request.theta;
  options.method = request.method;
  options.trace = true;                                  // the conformance row replays the points
  options.time_limit_seconds = request.timeout_seconds;  // in process: the engine must stop itself
  const auto t0 = std::chrono::steady_clock::now();
  try {
    lepp::RefineResult result = lepp::fast::refine(pslg, options);
    run.mesh = std::move(result.mesh);
    std::vector<lepp::Point> trace;
    for (const lepp::TraceStep& step : result.trace) trace.push_back(step.point);
    run.trace = std::move(trace);
    if (result.outcome == lepp::Outcome::TimeLimit) run.status = lepp::audit::RunStatus::TimedOut;
    else if (result.outcome != lepp::Outcome::Converged && result.outcome != lepp::Outcome::Unimprovable)
      run.status = lepp::audit::RunStatus::Stopped;
  } catch (const std::exception& e) {
    run.status = lepp::audit::RunStatus::Crashed;
    run.detail = e.what();
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return run;
}

int main() {
  lepp::audit::AuditOptions options;
  options.engine_name = "my engine";
  options.thetas = {20, 25, 30};
  options.cases = 60;
  options.inputs.paper = options.inputs.corpus = false;  // generated inputs only: no source tree needed
  options.inputs.seed = 1;
  options.out_dir = (std::filesystem::temp_directory_path() / "audit_my_engine").string();
  // In a child process per run: a hang is killed at the timeout, a crash is a finding, not the end of the audit.
  const lepp::audit::AuditReport report = lepp::audit::run_audit(lepp::audit::isolated_engine(my_engine), options);
  std::printf("%s", lepp::audit::markdown_report(report).c_str());
  return lepp::audit::exit_status(report);
}
