// SPDX-License-Identifier: GPL-3.0-or-later
#include "lepp/audit/audit.h"

#include <stdlib.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <set>

#include <fmt/format.h>

#include "lepp/audit/finding.h"
#include "lepp/audit/parallel.h"
#include "lepp/audit/points_cache.h"
#include "lepp/audit/shard.h"
#include "lepp/audit/shrink.h"
#include "lepp/audit/signature.h"
#include "lepp/audit/subprocess.h"
#include "lepp/audit/theta_text.h"
#include "lepp/io.h"

namespace fs = std::filesystem;

namespace lepp::audit {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Scratch directories for the runs, emptied before each: a few per thread
// (worker_index()), reused in turn so a long audit does not fill the disk.
class Scratch {
 public:
  explicit Scratch(std::string root) : root_(std::move(root)) {}
  std::string fresh() {
    const std::size_t w = worker_index();
    std::size_t k;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      k = counters_[w]++;
    }
    fs::path d = fs::path(root_) / fmt::format("run-{}-{}", w, k % 4);
    std::error_code ec;
    fs::remove_all(d, ec);
    fs::create_directories(d, ec);
    return d.string();
  }

 private:
  std::string root_;
  std::mutex mutex_;
  std::map<std::size_t, std::size_t> counters_;
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

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Whether two runs on the same input gave the same output (status, mesh bit for
// bit, trace); `why` says the first difference.
bool same_output(const EngineRun& a, const EngineRun& b, std::string& why) {
  if (a.status != b.status) {
    why = fmt::format("one run {}, the other {}", to_string(a.status), to_string(b.status));
    return false;
  }
  if (a.exit_code != b.exit_code || a.signal != b.signal) {
    why = fmt::format("exit status {} and {}, signal {} and {}", a.exit_code, b.exit_code, a.signal, b.signal);
    return false;
  }
  if (a.mesh.vertices.size() != b.mesh.vertices.size() || a.mesh.triangles.size() != b.mesh.triangles.size()) {
    why = fmt::format("{} vertices and {} triangles, then {} and {}", a.mesh.vertices.size(), a.mesh.triangles.size(),
                      b.mesh.vertices.size(), b.mesh.triangles.size());
    return false;
  }
  for (std::size_t i = 0; i < a.mesh.vertices.size(); ++i)
    if (!same_bits(a.mesh.vertices[i].x, b.mesh.vertices[i].x) || !same_bits(a.mesh.vertices[i].y, b.mesh.vertices[i].y)) {
      why = fmt::format("vertex {} at ({:.17g}, {:.17g}), then at ({:.17g}, {:.17g})", i, a.mesh.vertices[i].x,
                        a.mesh.vertices[i].y, b.mesh.vertices[i].x, b.mesh.vertices[i].y);
      return false;
    }
  for (std::size_t i = 0; i < a.mesh.triangles.size(); ++i)
    if (a.mesh.triangles[i] != b.mesh.triangles[i]) {
      why = fmt::format("triangle {} differs", i);
      return false;
    }
  if (a.trace.has_value() != b.trace.has_value() || (a.trace && a.trace->size() != b.trace->size())) {
    why = "the traces differ in length";
    return false;
  }
  if (a.trace)
    for (std::size_t i = 0; i < a.trace->size(); ++i)
      if (!same_bits((*a.trace)[i].x, (*b.trace)[i].x) || !same_bits((*a.trace)[i].y, (*b.trace)[i].y)) {
        why = fmt::format("trace point {} differs", i + 1);
        return false;
      }
  return true;
}

bool ended(RunStatus s) { return s != RunStatus::TimedOut && s != RunStatus::Stopped; }

// One case: an input at one theta, run `repeat` times, each run checked, and the
// comparison engines' points (from the cache when there).
struct CaseOutcome {
  std::vector<EngineRun> runs;       // kept only for runs some row failed or found on (for the findings)
  std::vector<CaseResult> results;   // one per repetition
  std::vector<RunStatus> statuses;
  std::string nondeterminism;        // the repeated runs differed: how
  std::vector<std::optional<double>> theirs;  // per comparison: its points added, when it finished
  double engine_seconds = 0, comparison_seconds = 0;
  double finished_seconds = -1;      // the engine's time on a run that ended (for the termination shrink's timeout)
  std::size_t comparison_runs = 0, cache_hits = 0;
  std::optional<OrderTermination> order_termination;  // lepp's orders where its fifo ends differently
};

// A failure chosen to be shrunk and saved.
struct FindingJob {
  std::size_t case_index = 0, repetition = 0;
  Row row = Row::Certificate;
  std::size_t number = 0;  // OUT/ROW-N
  bool internal = false;   // an internal error of the audit: OUT/internal-error-N
};

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
  if (opt.thetas.empty()) throw UsageError("--theta: no angle given");
  for (double t : opt.thetas)
    if (!(t > 0 && t < 60)) throw UsageError(fmt::format("--theta {}: must be between 0 and 60 degrees", t));
  if (opt.repeat < 1) throw UsageError("--repeat: at least 1");
  const bool sharded = opt.shard_count > 0;
  if (sharded && !(opt.shard_index >= 1 && opt.shard_index <= opt.shard_count))
    throw UsageError(fmt::format("--shard {}/{}: K must be between 1 and N", opt.shard_index, opt.shard_count));
  const auto t_start = Clock::now();
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
  for (std::size_t i = 0; i < kRows; ++i) rep.rows[i].row = kAllRows[i];
  const std::size_t jobs = rep.jobs;

  InputSources src = opt.inputs;
  src.count = std::max<std::size_t>(1, (opt.cases + opt.thetas.size() - 1) / opt.thetas.size());
  std::vector<AuditInput> inputs = collect_inputs(src, rep.skipped_inputs);
  rep.inputs = inputs.size();

  const std::string work_root = make_work_root(opt.work_dir);
  const bool own_work_root = opt.work_dir.empty();
  Scratch scratch(work_root);
  const PointsCache cache(opt.points_cache_dir);

  auto request_for = [&](double theta, double timeout) {
    EngineRequest r;
    r.method = opt.method;
    r.theta = theta;
    r.timeout_seconds = timeout;
    r.memory_mb = opt.memory_mb;
    r.work_dir = scratch.fresh();
    return r;
  };

  // The cases, input by input, each at every theta, up to --cases.
  // With --shard, every shard lists the same cases and keeps its own slice;
  // `index` is the case's place in the whole audit.
  struct Case {
    std::size_t input;
    double theta;
    std::size_t index;
  };
  std::vector<Case> cases;
  std::size_t all_cases = 0;
  for (std::size_t ii = 0; ii < inputs.size() && all_cases < opt.cases; ++ii)
    for (double theta : opt.thetas)
      if (all_cases < opt.cases) {
        if (!sharded || in_shard(all_cases, opt.shard_index, opt.shard_count)) cases.push_back({ii, theta, all_cases});
        ++all_cases;
      }
  const std::size_t total = cases.size();
  if (sharded) {
    rep.shard.emplace();
    rep.shard->index = opt.shard_index;
    rep.shard->count = opt.shard_count;
    rep.shard->total_cases = all_cases;
    rep.shard->config = shard_config(opt, inputs, all_cases);
    for (const Case& c : cases) rep.shard->cases.push_back(c.index);
  }
  auto run_ordinal = [&](const Case& c, std::size_t k) { return c.index * opt.repeat + k; };

  std::mutex progress_mutex;
  std::atomic<std::size_t> done{0}, failing{0};
  auto progress = [&](const std::string& what) {
    if (!opt.on_progress) return;
    std::lock_guard<std::mutex> lock(progress_mutex);
    opt.on_progress({done.load(), total, failing.load(), what});
  };

  // 1. Every case, `jobs` at a time: the program, the rows, the comparisons.
  std::vector<CaseOutcome> outcomes(total);
  parallel_for(total, jobs, [&](std::size_t ci) {
    const Case& c = cases[ci];
    const AuditInput& input = inputs[c.input];
    CaseOutcome& out = outcomes[ci];
    progress(input.name);
    std::optional<EngineRun> first;
    bool any_failed = false;
    for (std::size_t k = 0; k < opt.repeat; ++k) {
      EngineRequest req = request_for(c.theta, opt.timeout_seconds);
      const auto t0 = Clock::now();
      EngineRun run = engine(input.pslg, req);
      const double own = run.seconds > 0 ? run.seconds : since(t0);
      out.engine_seconds += own;
      if (ended(run.status)) out.finished_seconds = std::max(out.finished_seconds, own);
      CaseResult result = check_run(input.pslg, req, run, opt.checks);
      std::string why;
      if (first && out.nondeterminism.empty() && !same_output(*first, run, why))
        out.nondeterminism = fmt::format("runs 1 and {} differ: {}", k + 1, why);
      bool keep = false;
      for (Row row : kAllRows) {
        const Verdict v = result[row].verdict;
        keep = keep || v == Verdict::Failed || v == Verdict::Finding;
        any_failed = any_failed || v == Verdict::Failed;
      }
      out.statuses.push_back(run.status);
      out.results.push_back(std::move(result));
      if (!first) first = run;
      out.runs.push_back(keep ? std::move(run) : EngineRun{});
    }
    // Points added against the comparison engines, where both finished.
    const CaseResult& r0 = out.results.front();
    out.theirs.assign(opt.comparisons.size(), std::nullopt);
    if (out.statuses.front() == RunStatus::Ok && r0.steiner_points >= 0) {
      // A comparison only feeds the points ratio: it gets 50 times the audited
      // program's own time on this case rounded up to a power of two seconds, at
      // least a second, at most --timeout: a peer that hangs on an input (Triangle on
      // some of the hostile corpus) does not cost the whole timeout; a run cut short
      // drops out of the ratio.
      const double own = out.engine_seconds / static_cast<double>(opt.repeat);
      const double compare_timeout =
          opt.timeout_seconds > 0 ? std::min(opt.timeout_seconds, std::exp2(std::ceil(std::log2(std::max(1.0, 50 * own))))) : 0;
      for (std::size_t e = 0; e < opt.comparisons.size(); ++e) {
        const NamedEngine& other = opt.comparisons[e];
        // An entry of a run that did not finish (within at least a second, where the
        // audited program took 1/50 of its limit) is reused as it is: --no-cache reruns it.
        if (auto hit = cache.get(other.cache_key, input.pslg, c.theta, opt.method)) {
          ++out.cache_hits;
          if (hit->finished) out.theirs[e] = hit->points_added;
          continue;
        }
        const auto tc = Clock::now();
        EngineRun theirs = other.engine(input.pslg, request_for(c.theta, compare_timeout));
        out.comparison_seconds += since(tc);
        ++out.comparison_runs;
        CachedPoints value;
        value.finished = theirs.status == RunStatus::Ok;
        value.points_added = static_cast<double>(theirs.mesh.vertices.size()) - static_cast<double>(input.pslg.vertices.size());
        value.timeout_seconds = compare_timeout;
        cache.put(other.cache_key, input.pslg, c.theta, opt.method, value);
        if (value.finished) out.theirs[e] = value.points_added;
      }
    }
    // A termination difference with lepp's default order: which lepp orders end there.
    if (opt.compare_orders) {
      const auto tc = Clock::now();
      out.order_termination = compare_termination(input.pslg, input.name, opt.method, c.theta,
                                                  out.statuses.front() == RunStatus::Ok, opt.timeout_seconds);
      out.comparison_seconds += since(tc);
    }
    ++done;
    if (any_failed) ++failing;
  });

  // 2. The counts, in case order (the same report for any -j), and the failures to shrink.
  std::vector<std::vector<std::pair<double, double>>> points(opt.comparisons.size());  // (ours, theirs) per comparison
  std::set<std::pair<int, std::string>> chosen;
  std::vector<FindingJob> finding_jobs;
  std::array<std::size_t, kRows> planned{};
  std::size_t finding_number = 0, internal_planned = 0, internal_number = 0;
  double longest_finished = -1;  // the engine's longest finished run: the termination shrink's fallback clock
  std::map<std::size_t, double> finished_on_input;
  for (std::size_t ci = 0; ci < total; ++ci) {
    const Case& c = cases[ci];
    const AuditInput& input = inputs[c.input];
    CaseOutcome& out = outcomes[ci];
    rep.engine_seconds += out.engine_seconds;
    rep.comparison_seconds += out.comparison_seconds;
    rep.comparison_runs += out.comparison_runs;
    rep.comparison_cache_hits += out.cache_hits;
    if (out.order_termination) {
      rep.order_terminations.push_back(*out.order_termination);
      if (sharded) rep.shard->order_termination_cases.push_back(c.index);
    }
    longest_finished = std::max(longest_finished, out.finished_seconds);
    if (out.finished_seconds >= 0)
      finished_on_input[c.input] = std::max(finished_on_input.count(c.input) ? finished_on_input[c.input] : -1.0, out.finished_seconds);
    if (!out.nondeterminism.empty()) {
      ++rep.nondeterministic_cases;
      if (rep.nondeterministic_first.size() < 5) {
        rep.nondeterministic_first.push_back(fmt::format("{} at theta {}: {}", input.name, theta_text(c.theta), out.nondeterminism));
        if (sharded) rep.shard->nondeterministic_cases.push_back(c.index);
      }
    }
    ++rep.cases;
    const double ours = static_cast<double>(out.results.front().steiner_points);
    bool compared = false;
    for (std::size_t e = 0; e < opt.comparisons.size(); ++e) {
      if (!out.theirs[e]) continue;
      points[e].push_back({ours, *out.theirs[e]});
      compared = true;
    }
    if (sharded && compared) rep.shard->points.push_back({c.index, ours, out.theirs});
    for (std::size_t k = 0; k < out.results.size(); ++k) {
      const CaseResult& result = out.results[k];
      rep.status_counts[static_cast<int>(out.statuses[k])]++;
      // An internal error of the audit: counted once per run, the first few saved
      // (the row whose verdict code stopped first), the other rows counted as usual.
      for (Row row : kAllRows) {
        if (result[row].verdict != Verdict::InternalError) continue;
        ++rep.internal_error_runs;
        if (internal_planned < opt.max_findings_per_row && chosen.insert({-1, input.name}).second) {
          ++internal_planned;
          finding_jobs.push_back({ci, k, row, ++internal_number, true});
        }
        break;
      }
      rep.exempt_triangles += result.exempt_triangles;
      rep.runs_with_exempt += result.exempt_triangles > 0;
      rep.precision_exempt_triangles += result.precision_exempt_triangles;
      rep.runs_with_precision_exempt += result.precision_exempt_triangles > 0;
      for (Row row : kAllRows) {
        RowSummary& s = rep[row];
        const RowResult& r = result[row];
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
        if (r.verdict != Verdict::Failed && r.verdict != Verdict::Finding) continue;
        if (s.first_detail.empty()) {
          s.first_detail = fmt::format("{} at theta {}: {}", input.name, c.theta, r.detail);
          if (sharded) rep.shard->first_run[static_cast<std::size_t>(row)] = run_ordinal(c, k);
        }
        // Every deviation of the run's trace counts, each where it first showed.
        std::vector<DeviationLink> named = r.deviations;
        if (named.empty() && !r.deviation.empty()) named.push_back({r.deviation, static_cast<std::size_t>(r.step), 0});
        for (const DeviationLink& d : named) {
          if (r.verdict != Verdict::Failed || s.deviations[d.deviation]++ > 0) continue;
          s.deviation_first[d.deviation] =
              d.first_step > 0 ? fmt::format("step {} of {} at {} degrees", d.first_step, input.name, theta_text(c.theta))
                               : fmt::format("{} at {} degrees", input.name, theta_text(c.theta));  // a certificate's arithmetic
          if (sharded) rep.shard->deviation_first_run[static_cast<std::size_t>(row)][d.deviation] = run_ordinal(c, k);
        }
        if (r.verdict == Verdict::Failed && !r.deviation.empty() && r.consistent_variant) ++s.deviation_consistent[r.deviation];
        const std::size_t ri = static_cast<std::size_t>(row);
        if (planned[ri] >= opt.max_findings_per_row) continue;
        // One saved counterexample per input and row: the next ones come from other inputs.
        if (!chosen.insert({static_cast<int>(row), input.name}).second) continue;
        ++planned[ri];
        finding_jobs.push_back({ci, k, row, ++finding_number});
      }
    }
  }

  // 3. Each failure: run again on the input as found (is the program deterministic?),
  // shrink keeping its signature (candidates `jobs` at a time), run on the smallest, save.
  for (const FindingJob& job : finding_jobs) {
    const Case& c = cases[job.case_index];
    const AuditInput& input = inputs[c.input];
    const CaseOutcome& out = outcomes[job.case_index];
    const Row row = job.row;
    const EngineRun& found = out.runs[job.repetition];
    const RowResult& found_result = out.results[job.repetition][row];
    const double theta = c.theta;
    const auto ts = Clock::now();
    const FailureSignature want = failure_signature(row, input.pslg, found, found_result);

    Counterexample cx;
    cx.row = row;
    cx.input = input.name;
    cx.theta = theta;
    cx.dir = (fs::path(opt.out_dir) / fmt::format("{}-{}", job.internal ? "internal-error" : row_key(row), job.number)).string();
    cx.original_vertices = input.pslg.vertices.size();
    cx.original_segments = input.pslg.segments.size();
    cx.original_holes = input.pslg.holes.size();
    cx.original_detail = found_result.detail;
    cx.signature = want.text();

    // Every finding re-run before it is reported: a program whose output changes
    // between two runs on the same input gives counterexamples that may not reproduce.
    {
      EngineRequest q = request_for(theta, opt.timeout_seconds);
      EngineRun again = engine(input.pslg, q);
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
    double candidate_timeout = opt.timeout_seconds;
    if (row == Row::Termination && found.status == RunStatus::TimedOut) {
      const double own = finished_on_input.count(c.input) ? finished_on_input[c.input] : longest_finished;
      if (own >= 0) candidate_timeout = std::min(opt.timeout_seconds, std::max(1.0, 20 * own));
    }
    cx.shrink_timeout = candidate_timeout;

    ShrinkResult sh;
    sh.pslg = input.pslg;
    if (opt.shrink) {
      progress(fmt::format("shrinking a {} {}", row_key(row), to_string(want.verdict)));
      ShrinkLimits limits{opt.shrink_max_runs, opt.shrink_max_seconds, jobs};
      sh = shrink_input(
          input,
          [&](const Pslg& candidate) {
            // check_run turns its own errors into internal-error verdicts, which keep
            // only an internal-error finding; anything else thrown here is a candidate
            // not kept (shrink_input's fails_safely): the best input so far stays.
            EngineRequest q = request_for(theta, candidate_timeout);
            EngineRun again = engine(candidate, q);
            const CaseResult cr = check_run(candidate, q, again, opt.checks);
            return keeps(want, failure_signature(row, candidate, again, cr[row]));
          },
          limits);
    }
    // The final run on the smallest input, kept with the finding.
    Pslg smallest = sh.pslg;
    bool shrunk = opt.shrink && sh.steps > 0;
    EngineRequest q = request_for(theta, opt.timeout_seconds);
    EngineRun last = engine(smallest, q);
    CaseResult last_result = check_run(smallest, q, last, opt.checks);
    if (shrunk && !keeps(want, failure_signature(row, smallest, last, last_result[row]))) {
      // Not the same failure again (a flaky program, a candidate that ended just
      // past the shrink's shorter timeout): keep the input as found.
      shrunk = false;
      smallest = input.pslg;
      q = request_for(theta, opt.timeout_seconds);
      last = engine(smallest, q);
      last_result = check_run(smallest, q, last, opt.checks);
    }
    cx.vertices = smallest.vertices.size();
    cx.segments = smallest.segments.size();
    cx.holes = smallest.holes.size();
    cx.shrink_steps = shrunk ? sh.steps : 0;
    cx.shrink_runs = sh.runs;
    cx.detail = last_result[row].detail;
    cx.deviation = last_result[row].deviation;
    cx.deviations = last_result[row].deviations;
    // Absolute paths: reproduce.sh works from any directory.
    const fs::path abs_dir = fs::absolute(cx.dir).lexically_normal();
    if (!opt.reproduce_prefix.empty())
      cx.reproduce = fmt::format("{} --method {} --theta {} --timeout {} --compare none --inputs {}", opt.reproduce_prefix,
                                 to_string(opt.method), theta_text(theta), opt.timeout_seconds,
                                 shell_quote((abs_dir / "input.poly").string()));
    FindingText text{opt.engine_name, input.name, cx.reproduce, theta, opt.method};
    text.shrink_tried = opt.shrink;
    text.shrink_steps = cx.shrink_steps;
    text.original_vertices = cx.original_vertices;
    text.original_segments = cx.original_segments;
    text.original_holes = cx.original_holes;
    text.original_detail = cx.original_detail;
    text.signature = cx.signature;
    text.nondeterminism = cx.nondeterminism;
    try {
      save_finding(cx.dir, row, smallest, last, last_result[row], text);
      if (shrunk) {
        write_poly((fs::path(cx.dir) / "original.poly").string(), input.pslg);
        cx.original_input = (fs::path(cx.dir) / "original.poly").string();
      }
      if (!last.stderr_text.empty()) cx.stderr_file = (fs::path(cx.dir) / "stderr.txt").string();
    } catch (const std::exception& e) {
      cx.detail += fmt::format(" (could not save: {})", e.what());
    }
    if (sharded)
      rep.shard->findings.push_back({cx.dir, abs_dir.string(), run_ordinal(c, job.repetition), row, job.internal, input.name});
    (job.internal ? rep.internal_errors : rep[row].counterexamples).push_back(cx);
    rep.shrink_seconds += since(ts);
  }
  for (RowSummary& s : rep.rows)
    std::stable_sort(s.counterexamples.begin(), s.counterexamples.end(),
                     [](const Counterexample& a, const Counterexample& b) { return a.vertices < b.vertices; });
  if (opt.on_progress) opt.on_progress({total, total, failing.load(), ""});

  for (std::size_t e = 0; e < opt.comparisons.size(); ++e) rep.ratios.push_back(points_ratio(opt.comparisons[e].name, points[e]));
  if (own_work_root) {
    std::error_code ec;
    fs::remove_all(work_root, ec);
  }
  rep.seconds = since(t_start);
  // The audit's own time: the whole minus the program's, the comparisons' and the
  // shrinking's. With -j the parts overlap, so this is measured serially (-j 1).
  const double overhead = rep.seconds - rep.engine_seconds - rep.comparison_seconds - rep.shrink_seconds;
  rep.overhead_per_case_ms = rep.cases ? 1000 * std::max(0.0, overhead) / static_cast<double>(rep.cases) : 0;
  return rep;
}

}  // namespace lepp::audit
