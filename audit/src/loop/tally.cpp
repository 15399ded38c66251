// SPDX-License-Identifier: GPL-3.0-or-later
// The outcomes counted per row, and the failures to save chosen (loop/tally.h).
#include "loop/tally.h"

#include <algorithm>
#include <set>
#include <string>

#include <fmt/format.h>

#include "lepp/audit/theta_text.h"

namespace lepp::audit::loop {
namespace {

// Which failures are shrunk and saved: the first few per row (and of internal
// errors), one per input and row, numbered in case order.
class FindingChooser {
 public:
  FindingChooser(std::size_t max_per_row, std::vector<FindingJob>& jobs) : max_(max_per_row), jobs_(jobs) {}

  void internal_error(std::size_t ci, std::size_t k, Row row, const std::string& input) {
    if (internal_planned_ < max_ && chosen_.insert({-1, input}).second) {
      ++internal_planned_;
      jobs_.push_back({ci, k, row, ++internal_number_, true});
    }
  }

  void failure(std::size_t ci, std::size_t k, Row row, const std::string& input) {
    const std::size_t ri = static_cast<std::size_t>(row);
    if (planned_[ri] >= max_) return;
    // One saved counterexample per input and row: the next ones come from other inputs.
    if (!chosen_.insert({static_cast<int>(row), input}).second) return;
    ++planned_[ri];
    jobs_.push_back({ci, k, row, ++finding_number_});
  }

 private:
  const std::size_t max_;
  std::vector<FindingJob>& jobs_;
  std::set<std::pair<int, std::string>> chosen_;
  std::array<std::size_t, kRows> planned_{};
  std::size_t finding_number_ = 0, internal_planned_ = 0, internal_number_ = 0;
};

// What a case adds beyond its runs' rows: times, the order difference, the
// repeated runs' differences, the points against each comparison.
void count_case(AuditReport& rep, const AuditOptions& opt, const AuditInput& input, const Case& c, const CaseOutcome& out,
                Tally& tally) {
  rep.engine_seconds += out.engine_seconds;
  rep.comparison_seconds += out.comparison_seconds;
  rep.comparison_runs += out.comparison_runs;
  rep.comparison_cache_hits += out.cache_hits;
  if (out.order_termination) {
    rep.order_terminations.push_back(*out.order_termination);
    if (rep.shard) rep.shard->order_termination_cases.push_back(c.index);
  }
  tally.longest_finished = std::max(tally.longest_finished, out.finished_seconds);
  if (out.finished_seconds >= 0)
    tally.finished_on_input[c.input] =
        std::max(tally.finished_on_input.count(c.input) ? tally.finished_on_input[c.input] : -1.0, out.finished_seconds);
  if (!out.nondeterminism.empty()) {
    ++rep.nondeterministic_cases;
    if (rep.nondeterministic_first.size() < 5) {
      rep.nondeterministic_first.push_back(fmt::format("{} at theta {}: {}", input.name, theta_text(c.theta), out.nondeterminism));
      if (rep.shard) rep.shard->nondeterministic_cases.push_back(c.index);
    }
  }
  ++rep.cases;
  const double ours = static_cast<double>(out.results.front().steiner_points);
  bool compared = false;
  for (std::size_t e = 0; e < opt.comparisons.size(); ++e) {
    if (!out.theirs[e]) continue;
    tally.points[e].push_back({ours, *out.theirs[e]});
    compared = true;
  }
  if (rep.shard && compared) rep.shard->points.push_back({c.index, ours, out.theirs});
}

// One row of one run: its verdict counted, its deviations named, a failure offered to the chooser.
void count_row(AuditReport& rep, const AuditOptions& opt, const AuditInput& input, const Case& c, std::size_t ci,
               std::size_t k, Row row, const RowResult& r, FindingChooser& chooser) {
  RowSummary& s = rep[row];
  switch (r.verdict) {
    case Verdict::Held: ++s.run, ++s.held; break;
    case Verdict::Failed: ++s.run, ++s.failed; break;
    case Verdict::Finding: ++s.run, ++s.findings; break;
    case Verdict::NotApplicable: ++s.not_applicable; break;
    case Verdict::NotChecked: ++s.not_checked; break;
    case Verdict::InternalError: ++s.internal_errors; break;
  }
  // Steps accepted only under --arithmetic double: notes of a held run.
  for (const auto& [name, steps] : r.inexact_steps) ++s.inexact_runs[name], s.inexact_steps[name] += steps;
  if (r.verdict != Verdict::Failed && r.verdict != Verdict::Finding) return;
  if (s.first_detail.empty()) {
    s.first_detail = fmt::format("{} at theta {}: {}", input.name, c.theta, r.detail);
    if (rep.shard) rep.shard->first_run[static_cast<std::size_t>(row)] = run_ordinal(c, k, opt.repeat);
  }
  // Every deviation of the run's trace counts, each where it first showed.
  std::vector<DeviationLink> named = r.deviations;
  if (named.empty() && !r.deviation.empty()) named.push_back({r.deviation, static_cast<std::size_t>(r.step), 0});
  for (const DeviationLink& d : named) {
    if (r.verdict != Verdict::Failed || s.deviations[d.deviation]++ > 0) continue;
    s.deviation_first[d.deviation] =
        d.first_step > 0 ? fmt::format("step {} of {} at {} degrees", d.first_step, input.name, theta_text(c.theta))
                         : fmt::format("{} at {} degrees", input.name, theta_text(c.theta));  // a certificate's arithmetic
    if (rep.shard) rep.shard->deviation_first_run[static_cast<std::size_t>(row)][d.deviation] = run_ordinal(c, k, opt.repeat);
  }
  if (r.verdict == Verdict::Failed && !r.deviation.empty() && r.consistent_variant) ++s.deviation_consistent[r.deviation];
  chooser.failure(ci, k, row, input.name);
}

// One run: its status, an internal error of the audit, its exemptions, every row.
void count_run(AuditReport& rep, const AuditOptions& opt, const AuditInput& input, const Case& c, std::size_t ci,
               std::size_t k, RunStatus status, const CaseResult& result, FindingChooser& chooser) {
  rep.status_counts[static_cast<int>(status)]++;
  // An internal error of the audit: counted once per run, the first few saved
  // (the row whose verdict code stopped first), the other rows counted as usual.
  for (Row row : kAllRows) {
    if (result[row].verdict != Verdict::InternalError) continue;
    ++rep.internal_error_runs;
    chooser.internal_error(ci, k, row, input.name);
    break;
  }
  rep.exempt_triangles += result.exempt_triangles;
  rep.runs_with_exempt += result.exempt_triangles > 0;
  rep.precision_exempt_triangles += result.precision_exempt_triangles;
  rep.runs_with_precision_exempt += result.precision_exempt_triangles > 0;
  for (Row row : kAllRows) count_row(rep, opt, input, c, ci, k, row, result[row], chooser);
}

}  // namespace

Tally tally_cases(AuditReport& rep, const AuditOptions& opt, const std::vector<AuditInput>& inputs,
                  const std::vector<Case>& cases, const std::vector<CaseOutcome>& outcomes) {
  Tally tally;
  tally.points.resize(opt.comparisons.size());
  FindingChooser chooser(opt.max_findings_per_row, tally.finding_jobs);
  for (std::size_t ci = 0; ci < cases.size(); ++ci) {
    const Case& c = cases[ci];
    const AuditInput& input = inputs[c.input];
    const CaseOutcome& out = outcomes[ci];
    count_case(rep, opt, input, c, out, tally);
    for (std::size_t k = 0; k < out.results.size(); ++k)
      count_run(rep, opt, input, c, ci, k, out.statuses[k], out.results[k], chooser);
  }
  return tally;
}

}  // namespace lepp::audit::loop
