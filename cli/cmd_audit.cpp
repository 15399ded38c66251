// SPDX-License-Identifier: GPL-3.0-or-later
// `lepp audit (--cmd TEMPLATE | --engine NAME)`: certifies an implementation
// against the paper's statements on generated and real inputs, shrinks what
// fails (docs/AUDIT.md). Exit 0 every row holds, 1 findings, 2 bad usage.
// `lepp audit --shard K/N` runs one slice; `lepp audit merge SHARD.json...`
// makes the whole report of the slices' JSON reports (lepp/audit/report/shard.h).
// This file parses and prints; the audit is set up by lepp/engines/audit_setup.h and run by lepp::audit.
#include <unistd.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "message.h"
#include "lepp/audit/audit.h"
#include "lepp/audit/report/html.h"
#include "lepp/audit/report/report.h"
#include "lepp/audit/report/report_files.h"
#include "lepp/audit/report/shard_files.h"
#include "lepp/audit/request.h"
#include "lepp/engines/audit_setup.h"
#include "lepp/engines/registry.h"
#include "lepp/version.h"

namespace lepp::cli {
namespace {

struct MergeArgs {
  std::vector<std::string> shards;
  std::string out = "audit-out";
  // json: bare --json (or "-"): the JSON report on stdout instead of the markdown; --json FILE: to FILE,
  // as --json-file FILE (the older spelling, kept).
  std::string junit, json, json_file, html;
};

void print_progress(const audit::Progress& p) {
  message("\r\033[K%zu/%zu runs, %zu failing  %.60s", p.done, p.total, p.failed, p.current.c_str());
  if (p.done == p.total && p.current.empty()) message("\r\033[K");
  std::fflush(stderr);
}

// The report on stdout (markdown, or JSON), and to the files asked for; the audit's exit status.
int print_report(const audit::AuditReport& report, bool json, const std::string& json_file, const std::string& junit,
                 const std::string& html) {
  nlohmann::json j = audit::json_report(report);
  add_version(j);
  if (json)
    std::printf("%s\n", j.dump(2).c_str());
  else
    std::printf("%s", audit::markdown_report(report).c_str());
  if (const std::string error = audit::write_report_files(report, j, json_file, junit); !error.empty()) {
    message("lepp audit: %s\n", error.c_str());
    return 2;
  }
  if (!html.empty()) {
    if (const std::string error = audit::write_html_report(report, html); !error.empty()) {
      message("lepp audit: %s\n", error.c_str());
      return 2;
    }
  }
  return audit::exit_status(report);
}

int run_audit_command(const audit::AuditRequest& a, const std::string& html) {
  try {
    engines::AuditSetup setup = engines::audit_setup(a);
    if (isatty(STDERR_FILENO)) setup.options.on_progress = print_progress;
    const audit::AuditReport report = audit::run_audit(setup.engine, setup.options);
    return print_report(report, a.json, a.json_file, a.junit, html);
  } catch (const audit::UsageError& e) {
    message("lepp audit: %s\n", e.what());
    return 2;
  }
}

int run_merge_command(const MergeArgs& a) {
  try {
    std::vector<std::string> warnings;
    const bool json_stdout = a.json == "-";
    if (!json_stdout && !a.json.empty() && !a.json_file.empty())
      throw audit::UsageError("--json FILE and --json-file FILE: give one of them");
    const std::string json_file = json_stdout || a.json.empty() ? a.json_file : a.json;
    const audit::AuditReport report = audit::merge_shard_files(a.shards, a.out, json_file, warnings);
    for (const std::string& w : warnings) message("lepp audit merge: %s\n", w.c_str());
    return print_report(report, json_stdout, json_file, a.junit, a.html);
  } catch (const audit::UsageError& e) {
    message("lepp audit merge: %s\n", e.what());
    return 2;
  }
}

}  // namespace

void add_audit_command(CLI::App& app, int& status) {
  auto a = std::make_shared<audit::AuditRequest>();
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
  cmd->add_option("--tie-search-states", a->tie_search_states,
                  "The precision-limit search's bound, Lepp states per triangle, of the certificate and of lepp's built-in "
                  "engines (under audit and compared): beyond it no exemption (0: no bound; docs/CERTIFIER.md section 5c)")
      ->default_val(a->tie_search_states);
  cmd->add_option("--out", a->out, "Directory of the findings (ROW-N/: input.poly, out.*, finding.svg, reproduce.sh)")->default_val("audit-out");
  cmd->add_option("--junit", a->junit, "Also write the rows as JUnit XML to this file");
  cmd->add_flag("--json", a->json, "Print the report as JSON instead of markdown");
  cmd->add_option("--json-file", a->json_file, "Also write the JSON report to this file");
  auto html = std::make_shared<std::string>();
  cmd->add_option("--html", *html,
                  "Also write the report as one self-contained HTML page: the rows, the deviations by name, each finding "
                  "with the picture of its step and its reproduce command");
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
  // Bare --json prints JSON on stdout, as `lepp audit --json` does; --json FILE (or --json=FILE) still writes FILE.
  merge->add_option("--json", m->json,
                    "Print the report as JSON instead of markdown (as lepp audit --json); --json FILE: also write it to FILE "
                    "(as --json-file; -: on stdout)")
      ->expected(0, 1)
      ->default_str("-");
  merge->add_option("--json-file", m->json_file, "Also write the JSON report to this file");
  merge->add_option("--html", m->html, "Also write the report as one self-contained HTML page (as lepp audit --html)");
  merge->footer("Exit status: the audit's (0, 1, 3) as the whole audit run at once; 2 bad usage, or shards of different "
                "audits, a shard missing or given twice.");
  merge->callback([m, &status] { status = run_merge_command(*m); });
  cmd->footer("Exit status: 0 every row holds; 1 a row failed (findings saved under --out); 2 bad usage; 3 the audit's own "
              "verdict code failed on some run (internal-error findings saved; the report is written). docs/AUDIT.md.");
  cmd->callback([a, merge, html, &status] {
    if (merge->parsed()) return;  // `lepp audit merge`: its own callback ran
    status = run_audit_command(*a, *html);
  });
}

}  // namespace lepp::cli
