// SPDX-License-Identifier: GPL-3.0-or-later
#include "lepp/audit/audit.h"

#include <stdlib.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include <fmt/format.h>

#include "lepp/audit/command_engine.h"
#include "lepp/audit/finding.h"
#include "lepp/audit/shrink.h"

namespace fs = std::filesystem;

namespace lepp::audit {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// A scratch directory for one run, emptied first.
class Scratch {
 public:
  explicit Scratch(std::string root) : root_(std::move(root)) {}
  std::string fresh() {
    fs::path d = fs::path(root_) / fmt::format("run-{}", counter_++ % 4);
    std::error_code ec;
    fs::remove_all(d, ec);
    fs::create_directories(d, ec);
    return d.string();
  }
  const std::string& root() const { return root_; }

 private:
  std::string root_;
  std::size_t counter_ = 0;
};

std::string make_work_root(const std::string& wanted) {
  if (!wanted.empty()) {
    fs::create_directories(wanted);
    return wanted;
  }
  std::string templ = (fs::temp_directory_path() / "lepp-audit-XXXXXX").string();
  if (!mkdtemp(templ.data())) throw UsageError("cannot create a scratch directory in " + fs::temp_directory_path().string());
  return templ;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

}  // namespace

bool AuditReport::holds() const {
  for (const RowSummary& r : rows)
    if (!r.holds()) return false;
  return true;
}

int exit_status(const AuditReport& report) { return report.holds() ? 0 : 1; }

AuditReport run_audit(const Engine& engine, const AuditOptions& opt) {
  if (opt.thetas.empty()) throw UsageError("--theta: no angle given");
  for (double t : opt.thetas)
    if (!(t > 0 && t < 60)) throw UsageError(fmt::format("--theta {}: must be between 0 and 60 degrees", t));
  const auto t_start = Clock::now();
  AuditReport rep;
  rep.engine = opt.engine_name;
  rep.method = opt.method;
  rep.thetas = opt.thetas;
  rep.seed = opt.inputs.seed;
  rep.out_dir = opt.out_dir;
  rep.area_centroid = opt.checks.area_centroid;
  for (std::size_t i = 0; i < kRows; ++i) rep.rows[i].row = kAllRows[i];

  InputSources src = opt.inputs;
  src.count = std::max<std::size_t>(1, (opt.cases + opt.thetas.size() - 1) / opt.thetas.size());
  std::vector<AuditInput> inputs = collect_inputs(src, rep.skipped_inputs);
  rep.inputs = inputs.size();

  const std::string work_root = make_work_root(opt.work_dir);
  const bool own_work_root = opt.work_dir.empty();
  Scratch scratch(work_root);

  std::map<std::string, std::vector<double>> ratios;
  std::map<std::string, std::pair<double, double>> sums;
  std::size_t finding_number = 0;
  std::set<std::pair<int, std::string>> saved;

  auto request_for = [&](double theta, const std::string& dir) {
    EngineRequest r;
    r.method = opt.method;
    r.theta = theta;
    r.timeout_seconds = opt.timeout_seconds;
    r.memory_mb = opt.memory_mb;
    r.work_dir = dir;
    return r;
  };

  const std::size_t total = std::min(opt.cases, inputs.size() * opt.thetas.size());
  std::size_t done = 0, failures = 0;
  for (std::size_t ii = 0; ii < inputs.size() && done < total; ++ii) {
    const AuditInput& input = inputs[ii];
    for (double theta : opt.thetas) {
      if (done >= total) break;
      if (opt.on_progress) opt.on_progress({done, total, failures, input.name});
      EngineRequest req = request_for(theta, scratch.fresh());
      const auto t0 = Clock::now();
      EngineRun run = engine(input.pslg, req);
      rep.engine_seconds += run.seconds > 0 ? run.seconds : since(t0);
      rep.status_counts[static_cast<int>(run.status)]++;
      CaseResult result = check_run(input.pslg, req, run, opt.checks);
      rep.exempt_triangles += result.exempt_triangles;
      rep.runs_with_exempt += result.exempt_triangles > 0;
      ++done;
      ++rep.cases;

      // Points added against the comparison engines, where both finished.
      if (run.status == RunStatus::Ok && result.steiner_points >= 0) {
        for (const NamedEngine& other : opt.comparisons) {
          const auto tc = Clock::now();
          EngineRun theirs = other.engine(input.pslg, request_for(theta, scratch.fresh()));
          rep.comparison_seconds += since(tc);
          if (theirs.status != RunStatus::Ok) continue;
          double ours = static_cast<double>(result.steiner_points);
          double them = static_cast<double>(theirs.mesh.vertices.size()) - static_cast<double>(input.pslg.vertices.size());
          sums[other.name].first += ours;
          sums[other.name].second += them;
          if (them > 0) ratios[other.name].push_back(ours / them);
        }
      }

      bool any_failed = false;
      for (Row row : kAllRows) {
        RowSummary& s = rep[row];
        const RowResult& r = result[row];
        switch (r.verdict) {
          case Verdict::Held: ++s.run, ++s.held; break;
          case Verdict::Failed: ++s.run, ++s.failed; break;
          case Verdict::Finding: ++s.run, ++s.findings; break;
          case Verdict::NotApplicable: ++s.not_applicable; break;
          case Verdict::NotChecked: ++s.not_checked; break;
        }
        if (r.verdict != Verdict::Failed && r.verdict != Verdict::Finding) continue;
        any_failed = any_failed || r.verdict == Verdict::Failed;
        if (s.first_detail.empty()) s.first_detail = fmt::format("{} at theta {}: {}", input.name, theta, r.detail);
        if (r.verdict == Verdict::Failed && !r.deviation.empty() && s.deviations[r.deviation]++ == 0)
          s.deviation_first[r.deviation] = fmt::format("step {} of {} at {} degrees", r.step, input.name, theta_text(theta));
        if (r.verdict == Verdict::Failed && !r.deviation.empty() && r.consistent_variant) ++s.deviation_consistent[r.deviation];
        if (s.counterexamples.size() >= opt.max_findings_per_row) continue;
        // One saved counterexample per input and row: the next ones come from other inputs.
        if (!saved.insert({static_cast<int>(row), input.name}).second) continue;

        // Shrink through the engine: keep a smaller input when the same row still gives the same verdict.
        const auto ts = Clock::now();
        const Verdict want = r.verdict;
        Pslg smallest = input.pslg;
        ShrinkResult sh;
        sh.pslg = input.pslg;
        if (opt.shrink) {
          if (opt.on_progress) opt.on_progress({done, total, failures, fmt::format("shrinking a {} {}", row_key(row), to_string(want))});
          ShrinkLimits limits{opt.shrink_max_runs, opt.shrink_max_seconds};
          sh = shrink_input(
              input,
              [&](const Pslg& candidate) {
                EngineRequest q = request_for(theta, scratch.fresh());
                EngineRun again = engine(candidate, q);
                return check_run(candidate, q, again, opt.checks)[row].verdict == want;
              },
              limits);
          smallest = sh.pslg;
        }
        // The final run on the smallest input, kept with the finding.
        EngineRequest q = request_for(theta, scratch.fresh());
        EngineRun last = engine(smallest, q);
        CaseResult last_result = check_run(smallest, q, last, opt.checks);
        if (last_result[row].verdict != want) {  // flaky (a timeout near the limit): keep the original
          smallest = input.pslg;
          q = request_for(theta, scratch.fresh());
          last = engine(smallest, q);
          last_result = check_run(smallest, q, last, opt.checks);
        }
        Counterexample cx;
        cx.row = row;
        cx.input = input.name;
        cx.theta = theta;
        cx.dir = (fs::path(opt.out_dir) / fmt::format("{}-{}", row_key(row), ++finding_number)).string();
        cx.vertices = smallest.vertices.size();
        cx.segments = smallest.segments.size();
        cx.holes = smallest.holes.size();
        cx.original_vertices = input.pslg.vertices.size();
        cx.original_segments = input.pslg.segments.size();
        cx.original_holes = input.pslg.holes.size();
        cx.shrink_steps = sh.steps;
        cx.shrink_runs = sh.runs;
        cx.detail = last_result[row].detail;
        cx.deviation = last_result[row].deviation;
        if (!opt.reproduce_prefix.empty())
          cx.reproduce = fmt::format("{} --method {} --theta {} --timeout {} --inputs {}", opt.reproduce_prefix,
                                     to_string(opt.method), theta_text(theta), opt.timeout_seconds, cx.dir + "/input.poly");
        FindingText text{opt.engine_name, input.name, cx.reproduce, theta, opt.method};
        try {
          save_finding(cx.dir, row, smallest, last, last_result[row], text);
        } catch (const std::exception& e) {
          cx.detail += fmt::format(" (could not save: {})", e.what());
        }
        s.counterexamples.push_back(cx);
        std::sort(s.counterexamples.begin(), s.counterexamples.end(),
                  [](const Counterexample& a, const Counterexample& b) { return a.vertices < b.vertices; });
        rep.shrink_seconds += since(ts);
      }
      if (any_failed) ++failures;
    }
  }
  if (opt.on_progress) opt.on_progress({done, total, failures, ""});

  for (const NamedEngine& other : opt.comparisons) {
    PointsRatio pr;
    pr.against = other.name;
    const auto& v = ratios[other.name];
    pr.cases = v.size();
    if (!v.empty()) {
      pr.median = median(v);
      pr.max = *std::max_element(v.begin(), v.end());
      pr.min = *std::min_element(v.begin(), v.end());
    }
    const auto& s = sums[other.name];
    pr.total = s.second > 0 ? s.first / s.second : 0;
    rep.ratios.push_back(pr);
  }
  if (own_work_root) {
    std::error_code ec;
    fs::remove_all(work_root, ec);
  }
  rep.seconds = since(t_start);
  const double overhead = rep.seconds - rep.engine_seconds - rep.comparison_seconds - rep.shrink_seconds;
  rep.overhead_per_case_ms = rep.cases ? 1000 * std::max(0.0, overhead) / static_cast<double>(rep.cases) : 0;
  return rep;
}

}  // namespace lepp::audit
