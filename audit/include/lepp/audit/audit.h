// SPDX-License-Identifier: GPL-3.0-or-later
// The audit: runs an engine on every input at every theta, decides every row
// (judge/checks.h) for every run, shrinks each failure through the engine (shrink/shrink.h),
// saves it under the output directory (report/finding.h) and sums it all up per row.
// `lepp audit` is this plus option parsing and printing (report/report.h); the
// steps of run_audit are in src/loop/.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "lepp/audit/judge/checks.h"
#include "lepp/audit/judge/order_termination.h"
#include "lepp/audit/engine.h"
#include "lepp/audit/inputs/inputs.h"

namespace lepp::audit {

// Another engine run on the same inputs only to count its points (the ratio column).
struct NamedEngine {
  std::string name;
  Engine engine;
  std::string cache_key;  // the engine and its version, for the points cache (inputs/points_cache.h); empty: never cached
};

struct Progress {
  std::size_t done = 0, total = 0, failed = 0;
  std::string current;  // the input being run, or "shrinking ..."
};

struct AuditOptions {
  std::string engine_name = "engine";       // for the report
  std::string reproduce_prefix;             // e.g. "lepp audit --engine fast": findings get a one-line reproduce command
  Method method = Method::Centroid;
  std::vector<double> thetas = {20, 25, 30};
  std::size_t cases = 300;                  // runs at most (inputs x thetas)
  InputSources inputs;                      // count is derived from cases and thetas
  double timeout_seconds = 10;
  std::size_t memory_mb = 0;
  CheckOptions checks;
  std::string out_dir = "audit-out";        // findings go to OUT/ROW-N/
  std::string work_dir;                     // scratch; empty: a fresh directory under the system temp dir
  std::vector<NamedEngine> comparisons;     // points added compared against these (lepp reference, Triangle)
  std::string points_cache_dir;             // their points cached on disk here (inputs/points_cache.h); empty: not cached
  std::size_t jobs = 1;                     // cases, comparisons and shrink candidates run at once (0: the machine's cores)
  std::size_t repeat = 1;                   // every case run this many times, each run checked, the outputs compared
  bool shrink = true;
  bool compare_orders = true;               // a termination difference with lepp's fifo: which lepp orders end there
  std::size_t max_findings_per_row = 3;     // shrunk and saved; further failures are counted
  std::size_t shrink_max_runs = 300;        // engine runs per shrink at most
  double shrink_max_seconds = 60;           // and seconds per shrink
  // --shard K/N (lepp/audit/report/shard.h): only the cases whose index in the whole
  // audit is K-1 modulo N, and the report carries what merge_shards needs.
  // 0: the whole audit, no shard data.
  std::size_t shard_index = 0, shard_count = 0;
  std::function<void(const Progress&)> on_progress;
};

// A saved, shrunk counterexample.
struct Counterexample {
  Row row = Row::Certificate;
  std::string input;        // where it came from (before shrinking)
  std::string dir;          // OUT/ROW-N: input.poly, out.*, finding.svg, reproduce.sh, finding.md
  double theta = 0;
  std::size_t vertices = 0, segments = 0, holes = 0;  // of the shrunk input
  std::size_t original_vertices = 0, original_segments = 0, original_holes = 0;  // of the input as found
  std::size_t shrink_steps = 0, shrink_runs = 0;
  double shrink_timeout = 0;  // seconds per candidate run while shrinking (termination: from the program's own time)
  std::string signature;    // what every kept shrink step failed with, as the original (judge/signature.h)
  std::string detail;       // the row's one line on the shrunk input
  std::string deviation;    // conformance: the named deviation on the shrunk input (RowResult::deviation)
  std::vector<DeviationLink> deviations;  // conformance: every deviation of its trace (RowResult::deviations)
  // Conformance: why its chain stopped, by name ("" when it reached the trace's end or did
  // not go on; ConformanceFailure::chain_end_reason), and the program's mesh it was
  // followed on ("" the exact one; ConformanceFailure::mesh_reading).
  std::string chain_end_reason;
  std::string mesh_reading;
  std::string original_detail;  // the row's line on the input as found
  std::string original_input;   // DIR/original.poly, the input as found (when shrunk)
  bool deterministic = true;    // a second run on the input as found gave the same output
  std::string nondeterminism;   // else how the runs differed
  std::string stderr_file;      // DIR/stderr.txt when the program wrote to stderr
  std::string reproduce;    // one command line
};

struct RowSummary {
  Row row = Row::Certificate;
  std::size_t run = 0, held = 0, failed = 0, findings = 0, not_applicable = 0, not_checked = 0;
  std::size_t internal_errors = 0;  // runs this row's verdict code stopped on (undecided; Verdict::InternalError)
  std::vector<Counterexample> counterexamples;  // saved ones, smallest first
  std::string first_detail;                     // the first failure or finding seen, before shrinking
  // Conformance: failed runs by named deviation (every name of each run's
  // chain, RowResult::deviations), and where each was first seen
  // ("step 2 of corpus/paper/square400.poly at theta 25").
  std::map<std::string, std::size_t> deviations;
  std::map<std::string, std::string> deviation_first;
  std::map<std::string, std::size_t> deviation_consistent;  // of those, runs whose every traced step fits that one variant
  // Conformance under --arithmetic double: runs held with steps accepted only
  // under that reading, and those steps, by name ("inexact-length").
  std::map<std::string, std::size_t> inexact_runs, inexact_steps;
  bool holds() const { return failed == 0; }
};

struct PointsRatio {
  std::string against;
  std::size_t cases = 0;             // runs both finished
  double median = 0, max = 0, min = 0;
  double total = 0;                  // sum of ours / sum of theirs
};

// What one shard's report carries beyond a report, so that merge_shards
// (lepp/audit/report/shard.h) gives the whole audit's report: where each first, each
// listed item and each saved finding stands in the whole audit's order. A run's
// ordinal is case index x repeat + repetition, the order run_audit sums in.
struct ShardData {
  std::size_t index = 1, count = 1;
  std::size_t total_cases = 0;                  // cases of the whole audit
  std::vector<std::size_t> cases;               // this shard's, by their index in the whole audit
  nlohmann::json config;                        // what the shards of one audit share (shard_config)
  std::array<std::size_t, kRows> first_run{};   // ordinal of the run of each row's first_detail
  std::array<std::map<std::string, std::size_t>, kRows> deviation_first_run;  // of each deviation_first
  std::vector<std::size_t> nondeterministic_cases;   // case of each nondeterministic_first line
  std::vector<std::size_t> order_termination_cases;  // case of each order_terminations entry
  // Points added on each case some comparison finished on: ours, and each comparison's (none: it did not finish).
  struct Points {
    std::size_t case_index = 0;
    double ours = 0;
    std::vector<std::optional<double>> theirs;  // in the order of AuditOptions::comparisons
  };
  std::vector<Points> points;
  // Every finding this shard saved: the merge keeps those the whole audit would have saved.
  struct Finding {
    std::string dir, dir_absolute;  // Counterexample::dir, and where it was on the shard's machine
    std::size_t run = 0;            // the run's ordinal
    Row row = Row::Certificate;
    bool internal = false;          // an internal error of the audit (OUT/internal-error-N)
    std::string input;
  };
  std::vector<Finding> findings;
};

struct AuditReport {
  std::string engine;
  Method method = Method::Centroid;
  std::vector<double> thetas;
  std::uint64_t seed = 0;
  std::size_t inputs = 0, cases = 0;
  std::array<RowSummary, kRows> rows;
  bool area_centroid = false;                  // conformance checked against the declared area-centroid reading
  bool arithmetic_double = false;              // conformance checked against the declared arithmetic of doubles
  std::size_t tie_search_states = kTieSearchStates;  // the precision-limit searches' bound (CheckOptions)
  std::vector<PointsRatio> ratios;
  std::vector<OrderTermination> order_terminations;  // runs ending where lepp's fifo does not, or the reverse
  std::vector<std::string> skipped_inputs;
  std::size_t jobs = 1, repeat = 1;
  std::size_t nondeterministic_cases = 0;      // cases whose repeated runs (--repeat) gave different outputs
  std::vector<std::string> nondeterministic_first;  // the first few, with how they differed
  std::size_t comparison_runs = 0, comparison_cache_hits = 0;
  std::string points_cache_dir;
  std::size_t status_counts[6] = {};          // by RunStatus
  std::size_t exempt_triangles = 0, runs_with_exempt = 0;  // the small-input-angle rule at work
  std::size_t precision_exempt_triangles = 0, runs_with_precision_exempt = 0;  // the precision limit (CERTIFIER.md 5c)
  double seconds = 0;                          // whole audit
  double engine_seconds = 0;                   // the engine's own time (first runs, not shrinking)
  double comparison_seconds = 0, shrink_seconds = 0;
  double overhead_per_case_ms = 0;             // (seconds - engine - comparisons - shrinking) / cases
  std::string out_dir;
  // Runs on which the audit's own verdict code stopped (Verdict::InternalError on
  // some row): each such run is undecided, the first few saved as internal-error
  // findings (OUT/internal-error-N/, `row` the row whose code stopped), shrunk
  // like the others; the audit goes on with the other cases.
  std::size_t internal_error_runs = 0;
  std::vector<Counterexample> internal_errors;
  std::optional<ShardData> shard;              // --shard K/N: one slice of an audit, to be merged

  bool holds() const;                          // no row failed and no run hit an internal error
  RowSummary& operator[](Row r) { return rows[static_cast<std::size_t>(r)]; }
  const RowSummary& operator[](Row r) const { return rows[static_cast<std::size_t>(r)]; }
};

// Throws UsageError on bad options (no thetas, a missing input directory).
AuditReport run_audit(const Engine& engine, const AuditOptions& options);

// The ratio row against one comparison from (ours, theirs) per run both
// finished, in case order: the median, smallest and largest of ours/theirs
// (where theirs > 0), and the sum of ours over the sum of theirs.
PointsRatio points_ratio(const std::string& against, const std::vector<std::pair<double, double>>& ours_theirs);

// 3 the audit's own verdict code stopped on some run (internal errors; the
// report is complete otherwise), else 0 every row holds, 1 some row failed.
int exit_status(const AuditReport& report);

}  // namespace lepp::audit
