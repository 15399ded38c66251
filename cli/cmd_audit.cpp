// SPDX-License-Identifier: GPL-3.0-or-later
// `lepp audit (--cmd TEMPLATE | --engine NAME)`: certifies an implementation
// against the paper's statements on generated and real inputs, shrinks what
// fails (docs/AUDIT.md). Exit 0 every row holds, 1 findings, 2 bad usage.
// `lepp audit --shard K/N` runs one slice; `lepp audit merge SHARD.json...`
// makes the whole report of the slices' JSON reports (lepp/audit/report/shard.h).
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.h"
#include "lepp/audit/audit.h"
#include "lepp/audit/inputs/data_root.h"
#include "lepp/audit/inputs/points_cache.h"
#include "lepp/audit/report/report.h"
#include "lepp/audit/report/shard.h"
#include "lepp/audit/run/subprocess.h"
#include "lepp/engines/audited_engines.h"
#include "lepp/engines/command_engine.h"
#include "lepp/engines/registry.h"
#include "lepp/engines/builtin_engines.h"
#include "lepp/audit/run/isolated_engine.h"
#include "lepp/engines/peer_engines.h"
#include "lepp/fast.h"
#include "lepp/version.h"

namespace lepp::cli {
namespace {

struct AuditArgs {
  std::string cmd, engine;
  std::string method = to_string(Method::Centroid);
  std::string order = to_string(QueueOrder::Fifo);
  std::vector<double> thetas = {20, 25, 30};
  std::size_t cases = 300;
  std::uint64_t seed = 1;
  std::vector<std::string> inputs;
  std::string sources = "gen,paper,corpus";
  std::string compare = "auto";
  std::string root;  // empty: share/lepp beside the executable, else the source tree (data_root.h)
  double timeout = 10;
  std::size_t memory = 0;
  double angle_tolerance = 1e-3, point_tolerance = 8;
  std::string centroid = "vertex";
  std::string arithmetic = "exact";
  std::string out = "audit-out";
  std::string junit, json_file;
  bool json = false, no_shrink = false, no_isolate = false;
  std::size_t max_findings = 3;
  double shrink_seconds = 60;
  std::size_t jobs = 0;  // 0: the machine's cores
  std::size_t repeat = 1;
  std::string cache;     // empty: the default cache directory
  bool no_cache = false;
  std::string shard;     // K/N; empty: the whole audit
};

struct MergeArgs {
  std::vector<std::string> shards;
  std::string out = "audit-out";
  std::string junit, json;  // json: the JSON report to this file ("-": on stdout instead of the markdown)
};

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> parts;
  std::stringstream in(s);
  std::string p;
  while (std::getline(in, p, ','))
    if (!p.empty()) parts.push_back(p);
  return parts;
}

void print_progress(const audit::Progress& p) {
  std::fprintf(stderr, "\r\033[K%zu/%zu runs, %zu failing  %.60s", p.done, p.total, p.failed, p.current.c_str());
  if (p.done == p.total && p.current.empty()) std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
}

// The report on stdout (markdown, or JSON), and to the files asked for; the audit's exit status.
int print_report(const audit::AuditReport& report, bool json, const std::string& json_file, const std::string& junit) {
  nlohmann::json j = audit::json_report(report);
  add_version(j);
  if (json)
    std::printf("%s\n", j.dump(2).c_str());
  else
    std::printf("%s", audit::markdown_report(report).c_str());
  if (!json_file.empty()) {
    std::ofstream out(json_file);
    out << j.dump(2) << "\n";
    if (!out) {
      std::fprintf(stderr, "lepp audit: cannot write %s\n", json_file.c_str());
      return 2;
    }
  }
  if (!junit.empty()) {
    std::ofstream out(junit);
    out << audit::junit_report(report);
    if (!out) {
      std::fprintf(stderr, "lepp audit: cannot write %s\n", junit.c_str());
      return 2;
    }
  }
  return audit::exit_status(report);
}

int run_audit_command(const AuditArgs& args) {
  try {
    AuditArgs a = args;
    if (a.cmd.empty() == a.engine.empty()) throw audit::UsageError("give exactly one of --cmd TEMPLATE and --engine NAME");
    a.root = audit::find_data_root(a.root);
    // reproduce.sh names this very lepp: a bare `lepp` may not be on PATH, or be another one.
    const std::string self = audit::executable_path();
    const std::string lepp_word = self.empty() ? "lepp" : audit::shell_quote(self);
    audit::AuditOptions o;
    // The options' checks admit only the registry's names.
    o.method = *engines::parse_method(a.method);
    const QueueOrder order = *engines::parse_order(a.order);
    // lepp's engines in a child process unless --no-isolate (CGAL's always is: peer_engines.h).
    const bool isolate = !a.no_isolate;
    audit::Engine engine;
    if (!a.cmd.empty()) {
      engine = audit::command_engine(a.cmd);
      o.engine_name = a.cmd;
      o.reproduce_prefix = lepp_word + " audit --cmd " + audit::shell_quote(a.cmd);
    } else {
      const engines::Engine which = *engines::parse_engine(a.engine, engines::audit_engines());
      engine = engines::audited_engine(which, order, isolate, a.root);
      o.engine_name = engines::audit_title(which, order);
      o.reproduce_prefix = lepp_word + " audit --engine " + a.engine +
                           (order == QueueOrder::Fifo ? "" : std::string(" --order ") + to_string(order));
      if (which == engines::Engine::Triangle)
        o.reproduce_prefix += " --root " + audit::shell_quote(std::filesystem::absolute(a.root).string());
    }
    const bool automatic = a.compare == "auto";
    const std::vector<std::string> compare = automatic ? engines::names(engines::auto_comparisons()) : split(a.compare);
    for (const std::string& c : compare) {
      if (c == "none") continue;
      const std::optional<engines::Engine> which = engines::parse_engine(c, engines::comparison_engines());
      if (!which)
        throw audit::UsageError("--compare: unknown engine " + c + " (" + join(engines::names(engines::comparison_engines())) +
                                ", none)");
      // Cache keys name the engine's build: a new lepp or Triangle budget is a new entry.
      const std::string build = fmt::format("{} {}", kVersion, git_commit());
      try {
        o.comparisons.push_back(engines::comparison_engine(*which, isolate, a.root, build));
      } catch (const audit::UsageError&) {
        // Triangle missing: asked for explicitly, say so; under auto, compare without it.
        if (!automatic || *which != engines::Engine::Triangle) throw;
      }
    }
    o.thetas = a.thetas;
    o.cases = a.cases;
    o.inputs.seed = a.seed;
    o.inputs.dirs = a.inputs;
    o.inputs.source_root = a.root;
    auto sources = split(a.sources);
    auto has = [&](const char* s) { return std::find(sources.begin(), sources.end(), s) != sources.end(); };
    for (const std::string& s : sources)
      if (s != "gen" && s != "paper" && s != "corpus") throw audit::UsageError("--sources: unknown source " + s + " (gen, paper, corpus)");
    o.inputs.generated = has("gen");
    o.inputs.paper = has("paper");
    o.inputs.corpus = has("corpus");
    o.timeout_seconds = a.timeout;
    o.memory_mb = a.memory;
    // The replay makes exact rationals of both: a NaN or an infinity is bad usage here (in
    // the library it makes every run's conformance an internal error: the replay refuses it).
    if (!std::isfinite(a.angle_tolerance) || !std::isfinite(a.point_tolerance))
      throw audit::UsageError("--angle-tolerance and --point-tolerance must be finite numbers");
    o.checks.angle_tolerance_deg = a.angle_tolerance;
    o.checks.point_tolerance_ulps = a.point_tolerance;
    o.checks.area_centroid = a.centroid == "area";
    if (o.checks.area_centroid) o.reproduce_prefix += " --centroid area";
    o.checks.arithmetic_double = a.arithmetic == "double";
    if (o.checks.arithmetic_double) o.reproduce_prefix += " --arithmetic double";
    o.out_dir = a.out;
    o.shrink = !a.no_shrink;
    o.max_findings_per_row = a.max_findings;
    o.shrink_max_seconds = a.shrink_seconds;
    o.jobs = a.jobs;
    o.repeat = a.repeat;
    if (a.repeat < 1) throw audit::UsageError("--repeat: at least 1");
    o.points_cache_dir = a.no_cache ? std::string() : !a.cache.empty() ? a.cache : audit::default_points_cache_dir();
    if (!a.shard.empty()) {
      const audit::ShardSpec spec = audit::parse_shard(a.shard);
      o.shard_index = spec.index;
      o.shard_count = spec.count;
    }
    if (isatty(STDERR_FILENO)) o.on_progress = print_progress;

    audit::AuditReport report = audit::run_audit(engine, o);
    return print_report(report, a.json, a.json_file, a.junit);
  } catch (const audit::UsageError& e) {
    std::fprintf(stderr, "lepp audit: %s\n", e.what());
    return 2;
  }
}

int run_merge_command(const MergeArgs& a) {
  try {
    std::vector<audit::MergeInput> shards;
    for (const std::string& path : a.shards) {
      if (!a.json.empty() && a.json != "-" && std::filesystem::exists(a.json) && std::filesystem::exists(path) &&
          std::filesystem::equivalent(a.json, path))
        throw audit::UsageError("--json " + a.json + " is one of the shard reports: give another file");
      std::ifstream in(path);
      if (!in) throw audit::UsageError("cannot read " + path);
      nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
      if (j.is_discarded()) throw audit::UsageError(path + " is not JSON (a shard's report is lepp audit --shard K/N --json)");
      shards.push_back({std::move(j), path});
    }
    std::vector<std::string> warnings;
    audit::AuditReport report;
    try {
      report = audit::merge_shards(shards, a.out, warnings);
    } catch (const nlohmann::json::exception& e) {
      throw audit::UsageError(std::string("a shard report lacks a field or has a wrong one: ") + e.what());
    }
    for (const std::string& w : warnings) std::fprintf(stderr, "lepp audit merge: %s\n", w.c_str());
    return print_report(report, a.json == "-", a.json == "-" ? "" : a.json, a.junit);
  } catch (const audit::UsageError& e) {
    std::fprintf(stderr, "lepp audit merge: %s\n", e.what());
    return 2;
  }
}

}  // namespace

void add_audit_command(CLI::App& app, int& status) {
  auto a = std::make_shared<AuditArgs>();
  auto* cmd = app.add_subcommand("audit", "Audit a mesher (any program, or a built-in engine) against the paper's statements");
  cmd->add_option("--cmd", a->cmd, "Command template run per case: {in} .poly, {out} output prefix, {theta}, {method}");
  cmd->add_option("--engine", a->engine, "A built-in engine instead of --cmd")
      ->check(CLI::IsMember(engines::names(engines::audit_engines())));
  cmd->add_option("--method", a->method, "centroid or midpoint")->default_val(a->method)->check(CLI::IsMember(engines::method_names()));
  cmd->add_option("--order", a->order, "Queue order of the built-in lepp engines")
      ->default_val(a->order)
      ->check(CLI::IsMember(engines::order_names(engines::audit_orders())));
  cmd->add_option("--theta", a->thetas, "Smallest angles, degrees, comma-separated")->delimiter(',')->default_str("20,25,30");
  cmd->add_option("--cases", a->cases, "Runs at most (inputs x angles)")->default_val(300);
  cmd->add_option("--seed", a->seed, "Seed of the generated inputs")->default_val(1);
  cmd->add_option("--inputs", a->inputs, "A directory of .poly files (or one file): audit these instead of the built-in sources");
  cmd->add_option("--sources", a->sources, "Built-in inputs: gen (RapidCheck families), paper (corpus/paper), corpus (corpus/hostile)")
      ->default_val("gen,paper,corpus");
  cmd->add_option("--compare", a->compare, "Count points against: reference, fast, triangle, cgal, none (auto: reference and Triangle if installed)")
      ->default_val("auto");
  cmd->add_option("--root", a->root,
                  "Where corpus/paper, corpus/hostile (and tools/triangle/) are (default: share/lepp beside the executable, "
                  "else the source tree lepp was built from)");
  cmd->add_option("--timeout", a->timeout, "Seconds per run; a run past it is killed: a non-termination finding")->default_val(10);
  cmd->add_option("--memory", a->memory, "Address-space cap of the program, MB (0: none)")->default_val(0);
  cmd->add_flag("--no-isolate", a->no_isolate,
                "Run lepp's engines (fast, reference) in the audit's own process: no kill at the timeout, a crash ends the audit "
                "(for a debugger or a sanitizer; CGAL's is always run in a child)");
  cmd->add_option("--angle-tolerance", a->angle_tolerance, "Conformance: a triangle this close above theta (degrees) may count as bad or good")
      ->default_val(1e-3);
  cmd->add_option("--point-tolerance", a->point_tolerance, "Conformance: how far an inserted point may be from the paper's exact choice, in DBL_EPSILON x |coordinate|")
      ->default_val(8);
  cmd->add_option("--centroid", a->centroid,
                  "Conformance: the declared reading of the quad's centroid: vertex (the paper's (A+B+C+D)/4, Lemma 11) or area "
                  "(its centre of mass)")
      ->default_val("vertex")
      ->check(CLI::IsMember({"vertex", "area"}));
  cmd->add_option("--arithmetic", a->arithmetic,
                  "Conformance: the declared reading of the arithmetic: exact (every comparison exact) or double (the "
                  "paper's choice reached through two lengths within double rounding of a tie is accepted, as a note)")
      ->default_val("exact")
      ->check(CLI::IsMember({"exact", "double"}));
  cmd->add_option("--out", a->out, "Directory of the findings (ROW-N/: input.poly, out.*, finding.svg, reproduce.sh)")->default_val("audit-out");
  cmd->add_option("--junit", a->junit, "Also write the rows as JUnit XML to this file");
  cmd->add_flag("--json", a->json, "Print the report as JSON instead of markdown");
  cmd->add_option("--json-file", a->json_file, "Also write the JSON report to this file");
  cmd->add_flag("--no-shrink", a->no_shrink, "Save failures as found, without shrinking");
  cmd->add_option("--max-findings", a->max_findings, "Failures shrunk and saved per row (the rest are counted)")->default_val(3);
  cmd->add_option("--shrink-seconds", a->shrink_seconds, "Time budget of one shrink")->default_val(60);
  cmd->add_option("-j,--jobs", a->jobs, "Cases, comparisons and shrink candidates run at once (0: the machine's cores; 1 in a sanitizer build, whose fork is not safe beside threads)")
      ->default_val(0);
  cmd->add_option("--repeat", a->repeat, "Run every case N times: each run checked, the outputs compared (determinism)")
      ->default_val(1);
  cmd->add_option("--cache", a->cache,
                  "Directory of the comparison points cache (default: $XDG_CACHE_HOME/lepp/audit-points, else "
                  "~/.cache/lepp/audit-points)");
  cmd->add_flag("--no-cache", a->no_cache, "Run every comparison, read and write no cache");
  cmd->add_option("--shard", a->shard,
                  "K/N: run only the K-th of N disjoint slices of the cases (the same on every machine); "
                  "`lepp audit merge` combines the shards' --json reports");

  auto m = std::make_shared<MergeArgs>();
  auto* merge = cmd->add_subcommand("merge", "Combine the --json reports of all shards of one audit (--shard K/N) into its report");
  merge->add_option("shards", m->shards, "The shards' JSON reports (each shard once)")->required();
  merge->add_option("--out", m->out,
                    "Directory of the findings: each the whole audit keeps is copied here from its shard's --out (looked for "
                    "beside the shard's JSON, then where the shard wrote it)")
      ->default_val("audit-out");
  merge->add_option("--junit", m->junit, "Also write the rows as JUnit XML to this file");
  merge->add_option("--json", m->json, "Also write the JSON report to this file (-: on stdout instead of the markdown)");
  merge->footer("Exit status: the audit's (0, 1, 3) as the whole audit run at once; 2 bad usage, or shards of different "
                "audits, a shard missing or given twice.");
  merge->callback([m, &status] { status = run_merge_command(*m); });
  cmd->footer("Exit status: 0 every row holds; 1 a row failed (findings saved under --out); 2 bad usage; 3 the audit's own "
              "verdict code failed on some run (internal-error findings saved; the report is written). docs/AUDIT.md.");
  cmd->callback([a, merge, &status] {
    if (merge->parsed()) return;  // `lepp audit merge`: its own callback ran
    status = run_audit_command(*a);
  });
}

}  // namespace lepp::cli
