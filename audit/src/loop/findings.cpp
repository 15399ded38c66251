// SPDX-License-Identifier: GPL-3.0-or-later
// Failures re-run, shrunk and saved as findings (loop/findings.h).
#include "loop/findings.h"

#include <algorithm>
#include <filesystem>
#include <variant>

#include <fmt/format.h>

#include "lepp/audit/judge/diagnosis.h"
#include "lepp/audit/theta_text.h"
#include "lepp/audit/judge/signature.h"
#include "lepp/audit/report/finding.h"
#include "lepp/audit/run/subprocess.h"
#include "lepp/audit/shrink/shrink.h"
#include "lepp/io.h"
#include "loop/same_output.h"

namespace fs = std::filesystem;

namespace lepp::audit::loop {
namespace {

// The counterexample as found: where it goes, the input's size, the row's line, the signature to keep.
Counterexample as_found(const AuditOptions& opt, const FindingJob& job, const AuditInput& input, double theta,
                        const RowResult& found_result, const FailureSignature& want) {
  Counterexample cx;
  cx.row = job.row;
  cx.input = input.name;
  cx.theta = theta;
  cx.dir = (fs::path(opt.out_dir) / fmt::format("{}-{}", job.internal ? "internal-error" : row_key(job.row), job.number)).string();
  cx.original_vertices = input.pslg.vertices.size();
  cx.original_segments = input.pslg.segments.size();
  cx.original_holes = input.pslg.holes.size();
  cx.original_detail = found_result.detail;
  cx.signature = want.text();
  return cx;
}

// Every finding re-run before it is reported: a program whose output changes
// between two runs on the same input gives counterexamples that may not reproduce.
void check_determinism(AuditSession& session, const AuditInput& input, double theta, const EngineRun& found,
                       const CaseOutcome& out, Counterexample& cx) {
  EngineRequest q = session.request_for(theta, session.options.timeout_seconds);
  EngineRun again = session.engine(input.pslg, q);
  std::string why;
  if (!out.nondeterminism.empty()) {
    cx.deterministic = false;
    cx.nondeterminism = out.nondeterminism;
  } else if (!same_output(found, again, why)) {
    cx.deterministic = false;
    cx.nondeterminism = "two runs on the input as found differ: " + why;
  }
}

// Termination: a candidate that does not end costs its whole timeout, so
// candidates get one derived from the program's own time on this input (the
// longest run that ended, at any theta; else on any input), 20 times it and at
// least a second; the final run on the smallest input has the full --timeout.
double candidate_timeout(const AuditOptions& opt, Row row, const EngineRun& found, std::size_t input_index, const Tally& tally) {
  double timeout = opt.timeout_seconds;
  if (row == Row::Termination && found.status == RunStatus::TimedOut) {
    const auto on_input = tally.finished_on_input.find(input_index);
    const double own = on_input != tally.finished_on_input.end() ? on_input->second : tally.longest_finished;
    if (own >= 0) timeout = std::min(opt.timeout_seconds, std::max(1.0, 20 * own));
  }
  return timeout;
}

// Shrinking through the engine, keeping the failure's signature (candidates `jobs` at a time).
ShrinkResult shrink_failure(AuditSession& session, const AuditInput& input, Row row, double theta, double timeout,
                            const FailureSignature& want) {
  const AuditOptions& opt = session.options;
  ShrinkResult sh;
  sh.pslg = input.pslg;
  if (!opt.shrink) return sh;
  session.progress(fmt::format("shrinking a {} {}", row_key(row), to_string(want.verdict)));
  ShrinkLimits limits{opt.shrink_max_runs, opt.shrink_max_seconds, session.jobs};
  return shrink_input(
      input,
      [&](const Pslg& candidate) {
        // check_run turns its own errors into internal-error verdicts, which keep
        // only an internal-error finding; anything else thrown here is a candidate
        // not kept (shrink_input's fails_safely): the best input so far stays.
        EngineRequest q = session.request_for(theta, timeout);
        EngineRun again = session.engine(candidate, q);
        const CaseResult cr = check_run(candidate, q, again, opt.checks);
        return keeps(want, failure_signature(row, candidate, again, cr[row]));
      },
      limits);
}

// The final run on the smallest input, kept with the finding.
struct FinalRun {
  Pslg input;
  bool shrunk = false;
  EngineRun run;
  CaseResult result;
};

FinalRun final_run(AuditSession& session, const AuditInput& input, Row row, double theta, const ShrinkResult& sh,
                   const FailureSignature& want) {
  const AuditOptions& opt = session.options;
  FinalRun f;
  f.input = sh.pslg;
  f.shrunk = opt.shrink && sh.steps > 0;
  EngineRequest q = session.request_for(theta, opt.timeout_seconds);
  f.run = session.engine(f.input, q);
  f.result = check_run(f.input, q, f.run, opt.checks);
  if (f.shrunk && !keeps(want, failure_signature(row, f.input, f.run, f.result[row]))) {
    // Not the same failure again (a flaky program, a candidate that ended just
    // past the shrink's shorter timeout): keep the input as found.
    f.shrunk = false;
    f.input = input.pslg;
    q = session.request_for(theta, opt.timeout_seconds);
    f.run = session.engine(f.input, q);
    f.result = check_run(f.input, q, f.run, opt.checks);
  }
  return f;
}

// The finding's files under cx.dir: input.poly, out.*, finding.svg, reproduce.sh,
// finding.md, original.poly when shrunk, stderr.txt.
void write_finding(const AuditOptions& opt, const AuditInput& input, Row row, const FinalRun& last, Counterexample& cx) {
  FindingText text{opt.engine_name, input.name, cx.reproduce, cx.theta, opt.method};
  text.shrink_tried = opt.shrink;
  text.shrink_steps = cx.shrink_steps;
  text.original_vertices = cx.original_vertices;
  text.original_segments = cx.original_segments;
  text.original_holes = cx.original_holes;
  text.original_detail = cx.original_detail;
  text.signature = cx.signature;
  text.nondeterminism = cx.nondeterminism;
  try {
    save_finding(cx.dir, row, last.input, last.run, last.result[row], text);
    if (last.shrunk) {
      write_poly((fs::path(cx.dir) / "original.poly").string(), input.pslg);
      cx.original_input = (fs::path(cx.dir) / "original.poly").string();
    }
    if (!last.run.stderr_text.empty()) cx.stderr_file = (fs::path(cx.dir) / "stderr.txt").string();
  } catch (const std::exception& e) {
    cx.detail += fmt::format(" (could not save: {})", e.what());
  }
}

void save_one(AuditReport& rep, AuditSession& session, const AuditInput& input, const Case& c, const CaseOutcome& out,
              const FindingJob& job, const Tally& tally) {
  const AuditOptions& opt = session.options;
  const Row row = job.row;
  const EngineRun& found = out.runs[job.repetition];
  const RowResult& found_result = out.results[job.repetition][row];
  const double theta = c.theta;
  const auto ts = Clock::now();
  const FailureSignature want = failure_signature(row, input.pslg, found, found_result);

  Counterexample cx = as_found(opt, job, input, theta, found_result, want);
  check_determinism(session, input, theta, found, out, cx);
  cx.shrink_timeout = candidate_timeout(opt, row, found, c.input, tally);
  const ShrinkResult sh = shrink_failure(session, input, row, theta, cx.shrink_timeout, want);
  const FinalRun last = final_run(session, input, row, theta, sh, want);
  cx.vertices = last.input.vertices.size();
  cx.segments = last.input.segments.size();
  cx.holes = last.input.holes.size();
  cx.shrink_steps = last.shrunk ? sh.steps : 0;
  cx.shrink_runs = sh.runs;
  cx.detail = last.result[row].detail;
  cx.deviation = last.result[row].deviation;
  cx.deviations = last.result[row].deviations;
  if (const auto& d = last.result[row].diagnosis)
    if (const auto* f = std::get_if<ConformanceFailure>(&d->failure)) {
      cx.chain_end_reason = f->chain_end_reason;
      cx.mesh_reading = f->mesh_reading;
    }
  // Absolute paths: reproduce.sh works from any directory.
  const fs::path abs_dir = fs::absolute(cx.dir).lexically_normal();
  if (!opt.reproduce_prefix.empty())
    cx.reproduce = fmt::format("{} --method {} --theta {} --timeout {} --compare none --inputs {}", opt.reproduce_prefix,
                               to_string(opt.method), theta_text(theta), opt.timeout_seconds,
                               shell_quote((abs_dir / "input.poly").string()));
  write_finding(opt, input, row, last, cx);
  if (rep.shard)
    rep.shard->findings.push_back({cx.dir, abs_dir.string(), run_ordinal(c, job.repetition, opt.repeat), row, job.internal, input.name});
  (job.internal ? rep.internal_errors : rep[row].counterexamples).push_back(cx);
  rep.shrink_seconds += since(ts);
}

}  // namespace

void save_findings(AuditReport& rep, AuditSession& session, const std::vector<AuditInput>& inputs,
                   const std::vector<Case>& cases, const std::vector<CaseOutcome>& outcomes, const Tally& tally) {
  for (const FindingJob& job : tally.finding_jobs) {
    const Case& c = cases[job.case_index];
    save_one(rep, session, inputs[c.input], c, outcomes[job.case_index], job, tally);
  }
  for (RowSummary& s : rep.rows)
    std::stable_sort(s.counterexamples.begin(), s.counterexamples.end(),
                     [](const Counterexample& a, const Counterexample& b) { return a.vertices < b.vertices; });
}

}  // namespace lepp::audit::loop
