// SPDX-License-Identifier: GPL-3.0-or-later
// run_audit: the audit as a few named steps (their code in loop/), and the report's verdicts.
#include "lepp/audit/audit.h"

#include <algorithm>

#include <fmt/format.h>

#include "lepp/audit/report/finding.h"
#include "lepp/audit/run/parallel.h"
#include "lepp/audit/inputs/points_cache.h"
#include "lepp/audit/report/shard.h"
#include "lepp/audit/shrink/shrink.h"
#include "lepp/audit/judge/signature.h"
#include "lepp/audit/run/subprocess.h"
#include "lepp/audit/theta_text.h"
#include "lepp/io.h"

namespace fs = std::filesystem;
#include "loop/cases.h"
#include "loop/findings.h"
#include "loop/session.h"
#include "loop/tally.h"

namespace lepp::audit {
namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

void check_options(const AuditOptions& opt) {
  if (opt.thetas.empty()) throw UsageError("--theta: no angle given");
  for (double t : opt.thetas)
    if (!(t > 0 && t < 60)) throw UsageError(fmt::format("--theta {}: must be between 0 and 60 degrees", t));
  if (opt.repeat < 1) throw UsageError("--repeat: at least 1");
  if (opt.shard_count > 0 && !(opt.shard_index >= 1 && opt.shard_index <= opt.shard_count))
    throw UsageError(fmt::format("--shard {}/{}: K must be between 1 and N", opt.shard_index, opt.shard_count));
}

// The report before any run: what was asked for.
AuditReport empty_report(const AuditOptions& opt) {
  AuditReport rep;
  rep.engine = opt.engine_name;
  rep.method = opt.method;
  rep.thetas = opt.thetas;
  rep.seed = opt.inputs.seed;
  rep.out_dir = opt.out_dir;
  rep.jobs = resolve_jobs(opt.jobs);
  rep.repeat = opt.repeat;
  rep.points_cache_dir = opt.points_cache_dir;
  rep.area_centroid = opt.checks.area_centroid;
  rep.arithmetic_double = opt.checks.arithmetic_double;
  rep.tie_search_states = opt.checks.tie_search_states;
  for (std::size_t i = 0; i < kRows; ++i) rep.rows[i].row = kAllRows[i];
  return rep;
}

// As many inputs as --cases needs at every theta; the skipped ones noted in the report.
std::vector<AuditInput> audit_inputs(const AuditOptions& opt, AuditReport& rep) {
  InputSources src = opt.inputs;
  src.count = std::max<std::size_t>(1, (opt.cases + opt.thetas.size() - 1) / opt.thetas.size());
  std::vector<AuditInput> inputs = collect_inputs(src, rep.skipped_inputs);
  rep.inputs = inputs.size();
  return inputs;
}

// --shard K/N: the report carries this slice's cases and what merge_shards needs.
void start_shard_data(AuditReport& rep, const AuditOptions& opt, const std::vector<AuditInput>& inputs, const loop::CasePlan& plan) {
  rep.shard.emplace();
  rep.shard->index = opt.shard_index;
  rep.shard->count = opt.shard_count;
  rep.shard->total_cases = plan.all_cases;
  rep.shard->config = shard_config(opt, inputs, plan.all_cases);
  for (const loop::Case& c : plan.cases) rep.shard->cases.push_back(c.index);
}

// The points ratios, the scratch removed, the times.
void finish_report(AuditReport& rep, loop::AuditSession& session, const loop::Tally& tally, loop::Clock::time_point t_start) {
  const AuditOptions& opt = session.options;
  session.progress_finished();
  for (std::size_t e = 0; e < opt.comparisons.size(); ++e) rep.ratios.push_back(points_ratio(opt.comparisons[e].name, tally.points[e]));
  session.remove_own_work_root();
  rep.seconds = loop::since(t_start);
  // The audit's own time: the whole minus the program's, the comparisons' and the
  // shrinking's. With -j the parts overlap, so this is measured serially (-j 1).
  const double overhead = rep.seconds - rep.engine_seconds - rep.comparison_seconds - rep.shrink_seconds;
  rep.overhead_per_case_ms = rep.cases ? 1000 * std::max(0.0, overhead) / static_cast<double>(rep.cases) : 0;
}

}  // namespace

bool AuditReport::holds() const {
  for (const RowSummary& r : rows)
    if (!r.holds()) return false;
  return internal_error_runs == 0;
}

PointsRatio points_ratio(const std::string& against, const std::vector<std::pair<double, double>>& ours_theirs) {
  PointsRatio pr;
  pr.against = against;
  std::vector<double> v;
  double ours = 0, theirs = 0;
  for (const auto& [o, t] : ours_theirs) {
    ours += o;
    theirs += t;
    if (t > 0) v.push_back(o / t);
  }
  pr.cases = v.size();
  if (!v.empty()) {
    pr.median = median(v);
    pr.max = *std::max_element(v.begin(), v.end());
    pr.min = *std::min_element(v.begin(), v.end());
  }
  pr.total = theirs > 0 ? ours / theirs : 0;
  return pr;
}

int exit_status(const AuditReport& report) {
  if (report.internal_error_runs > 0) return 3;  // the audit itself failed somewhere: some runs are undecided
  return report.holds() ? 0 : 1;
}

AuditReport run_audit(const Engine& engine, const AuditOptions& opt) {
  check_options(opt);
  const auto t_start = loop::Clock::now();
  AuditReport rep = empty_report(opt);
  const std::vector<AuditInput> inputs = audit_inputs(opt, rep);
  const loop::CasePlan plan = loop::plan_cases(opt, inputs.size());
  if (opt.shard_count > 0) start_shard_data(rep, opt, inputs, plan);
  loop::AuditSession session(engine, opt, rep.jobs, plan.cases.size());
  // 1. Every case, `jobs` at a time: the program, the rows, the comparisons.
  const std::vector<loop::CaseOutcome> outcomes = loop::run_cases(session, inputs, plan.cases);
  // 2. The counts, in case order (the same report for any -j), and the failures to shrink.
  const loop::Tally tally = loop::tally_cases(rep, opt, inputs, plan.cases, outcomes);
  // 3. Each failure: run again, shrunk, run on the smallest input, saved.
  loop::save_findings(rep, session, inputs, plan.cases, outcomes, tally);
  finish_report(rep, session, tally, t_start);
  return rep;
}

}  // namespace lepp::audit
