// SPDX-License-Identifier: GPL-3.0-or-later
// The audit report as markdown, JSON and JUnit XML.
#include "lepp/audit/report/report.h"

#include <fmt/format.h>

#include "lepp/audit/report/shard.h"
#include "lepp/audit/theta_text.h"
#include "row_verdict.h"
#include "xml_escape.h"

namespace lepp::audit {
namespace {

using detail::xml_escape;

std::string smallest_cell(const RowSummary& r) {
  if (r.counterexamples.empty()) return r.first_detail.empty() ? "" : md_cell(r.first_detail);
  const Counterexample& c = r.counterexamples.front();
  if (c.shrink_steps == 0)
    return fmt::format("`{}` ({} vertices, {} segments, as found; theta {})", c.dir, c.vertices, c.segments, theta_text(c.theta));
  return fmt::format("`{}` ({} vertices, {} segments, shrunk from {} vertices, {} segments; theta {})", c.dir, c.vertices,
                     c.segments, c.original_vertices, c.original_segments, theta_text(c.theta));
}

}  // namespace

nlohmann::json deviations_json(const std::vector<DeviationLink>& chain) {
  nlohmann::json out = nlohmann::json::array();
  for (const DeviationLink& l : chain) out.push_back({{"deviation", l.deviation}, {"from_step", l.first_step}, {"steps", l.steps}});
  return out;
}

std::vector<DeviationLink> deviations_of(const nlohmann::json& chain) {
  std::vector<DeviationLink> out;
  for (const nlohmann::json& l : chain)
    out.push_back({l.at("deviation").get<std::string>(), l.at("from_step").get<std::size_t>(), l.at("steps").get<std::size_t>()});
  return out;
}

std::string deviations_text(const AuditReport& rep) {
  const RowSummary& r = rep[Row::Conformance];
  std::string md;
  // The certifier's failures the program's arithmetic explains (judge/arithmetic.h).
  for (Row row : {Row::Certificate, Row::MinAngle}) {
    const RowSummary& named = rep[row];
    if (named.deviations.empty()) continue;
    md += fmt::format("\n{} failures named by the program's arithmetic (its output's coordinates, or its rounding: "
                      "docs/CONFORMANCE.md \"Arithmetic\"):",
                      row == Row::Certificate ? "Certificate" : "Min-angle");
    bool first = true;
    for (const auto& [name, runs] : named.deviations) {
      auto it = named.deviation_first.find(name);
      md += fmt::format("{} {}: {} run{}{}", first ? "" : ";", name, runs, runs == 1 ? "" : "s",
                        it != named.deviation_first.end() ? ", first at " + it->second : "");
      first = false;
    }
    md += ".\n";
  }
  if (rep.area_centroid)
    md += "\nConformance is checked against the declared reading `--centroid area`: the quad centroid is its area "
          "centroid (centre of mass), not the paper's vertex average (A+B+C+D)/4 of Lemma 11.\n";
  md += rep.arithmetic_double
            ? "\nArithmetic reading `--arithmetic double`: a step that is the paper's choice once two edge lengths within "
              "double rounding of each other count as a tie (inexact-length), or once a triangle within double rounding "
              "above theta counts as bad (inexact-threshold), is accepted, and so are a triangle below theta and an edge "
              "not locally Delaunay by no more than double rounding (inexact-threshold, inexact-incircle); each is counted "
              "below as a note.\n"
            : "\nArithmetic reading `exact` (the default; `--arithmetic double` accepts the paper's choice reached through "
              "lengths within double rounding of a tie, and angles and in-circle tests within double rounding).\n";
  // Notes: conformance steps, and the certifier's edges and triangles within rounding.
  for (Row row : {Row::Certificate, Row::MinAngle, Row::Conformance}) {
    const RowSummary& noted = rep[row];
    const char* unit = row == Row::Certificate ? "edge" : row == Row::MinAngle ? "triangle" : "step";
    const char* held = row == Row::Certificate ? "whose certificate holds" : row == Row::MinAngle ? "whose angles hold" : "that conform";
    for (const auto& [name, steps] : noted.inexact_steps) {
      const std::size_t runs = noted.inexact_runs.count(name) ? noted.inexact_runs.at(name) : 0;
      md += fmt::format("Notes under `--arithmetic double`: {}: {} {}{} in {} run{} {}.\n", name, steps, unit,
                        steps == 1 ? "" : "s", runs, runs == 1 ? "" : "s", held);
    }
  }
  if (r.deviations.empty()) return md;
  md += "\nConformance deviations (every catalogue rule each failing run's trace shows, in runs; docs/CONFORMANCE.md):";
  std::size_t named = 0;
  bool first = true;
  for (const auto& [name, runs] : r.deviations) {
    named += runs;
    auto it = r.deviation_first.find(name);
    md += fmt::format("{} {}: {} run{}", first ? "" : ";", name, runs, runs == 1 ? "" : "s");
    if (it != r.deviation_first.end()) md += ", first at " + it->second;
    auto c = r.deviation_consistent.find(name);
    if (c != r.deviation_consistent.end() && c->second > 0)
      md += fmt::format(" (every traced step of {} of them fits {} as one consistent variant)", c->second, name);
    first = false;
  }
  md += ".\n";
  if (r.deviations.size() == 1) {
    const auto& [name, runs] = *r.deviations.begin();
    auto c = r.deviation_consistent.find(name);
    if (runs == r.failed && c != r.deviation_consistent.end() && c->second == runs)
      md += fmt::format("Every traced step of the program fits one consistent variant: {} in place of the paper's rule where they "
                        "differ ({} of {} failing runs).\n",
                        name, runs, r.failed);
  }
  return md;
}

std::string md_cell(const std::string& s) {
  std::string r;
  for (char c : s) r += c == '|' ? std::string("\\|") : c == '\n' ? std::string(" ") : std::string(1, c);
  return r.size() > 200 ? r.substr(0, 200) + "..." : r;
}

std::string markdown_report(const AuditReport& rep) {
  std::string md = fmt::format("# lepp audit: {}\n\n", rep.engine);
  md += fmt::format("Method {}, theta {}; {} runs on {} inputs (seed {}{}); {:.1f} s with -j {}, of which the engine {:.1f} s.\n\n",
                    to_string(rep.method), thetas_text(rep.thetas), rep.cases, rep.inputs, rep.seed,
                    rep.repeat > 1 ? fmt::format(", each case run {} times", rep.repeat) : "", rep.seconds, rep.jobs,
                    rep.engine_seconds);
  if (rep.shard)
    md += fmt::format("Shard {} of {}: {} of the audit's {} cases; `lepp audit merge` makes the whole report of the shards' "
                      "`--json` reports.\n\n",
                      rep.shard->index, rep.shard->count, rep.shard->cases.size(), rep.shard->total_cases);
  md += "| # | check | paper | runs | held | failed | verdict | smallest counterexample |\n";
  md += "|---|---|---|---:|---:|---:|---|---|\n";
  for (std::size_t i = 0; i < kRows; ++i) {
    const RowSummary& r = rep.rows[i];
    std::string failed = std::to_string(r.failed);
    if (r.findings) failed += fmt::format(" (+{} findings)", r.findings);
    md += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} |\n", i + 1, row_key(r.row), md_cell(row_passage(r.row)),
                      r.run, r.held, failed, detail::row_verdict(r), smallest_cell(r));
  }
  md += deviations_text(rep);
  if (rep.internal_error_runs > 0) {
    md += fmt::format("\n**The audit itself failed on {} run{}**: its own verdict code (the certifier, the conformance replay) "
                      "stopped, so {} undecided; not a failure of the program. Undecided:",
                      rep.internal_error_runs, rep.internal_error_runs == 1 ? "" : "s",
                      rep.internal_error_runs == 1 ? "that run's rows are" : "those runs' rows are");
    for (const RowSummary& r : rep.rows)
      if (r.internal_errors) md += fmt::format(" {} {},", row_key(r.row), r.internal_errors);
    md.pop_back();
    md += ". Each saved one is under \"Internal errors of the audit\" below; please report it with its directory.\n";
  }
  md += "\nRuns a row did not apply to: ";
  for (std::size_t i = 0; i < kRows; ++i) {
    const RowSummary& r = rep.rows[i];
    md += fmt::format("{}{} {} n/a, {} not checked", i ? "; " : "", row_key(r.row), r.not_applicable, r.not_checked);
  }
  md += fmt::format(".\n\nSmall-input-angle exemptions: {} triangles below theta in {} runs exempt by the rule (docs/CERTIFIER.md), not counted as violations.\n", rep.exempt_triangles, rep.runs_with_exempt);
  if (rep.precision_exempt_triangles > 0)  // said only when it happened: most audits never reach the limit of doubles
    md += fmt::format("\nPrecision-limit exemptions: {} triangles below theta in {} runs for which no point the method allows can be "
                      "inserted as rounded to doubles (docs/CERTIFIER.md section 5c), not counted as violations.\n",
                      rep.precision_exempt_triangles, rep.runs_with_precision_exempt);
  if (rep.tie_search_states != kTieSearchStates)  // the default goes without saying
    md += fmt::format("\nTie search bound `--tie-search-states {}`: the precision-limit searches of the certificate and of lepp's "
                      "built-in engines visit {} per triangle (default {}; docs/CERTIFIER.md section 5c).\n",
                      rep.tie_search_states,
                      rep.tie_search_states == 0 ? std::string("any number of Lepp states")
                                                 : fmt::format("at most {} Lepp states", rep.tie_search_states),
                      kTieSearchStates);
  md += "\nHow the runs ended:";
  for (int s = 0; s < 6; ++s)
    if (rep.status_counts[s]) md += fmt::format(" {} {},", to_string(static_cast<RunStatus>(s)), rep.status_counts[s]);
  if (md.back() == ',') md.pop_back();
  md += ".\n";
  if (rep.nondeterministic_cases > 0) {
    md += fmt::format("\n**Not deterministic**: in {} cases the repeated runs on the same input gave different outputs:\n",
                      rep.nondeterministic_cases);
    for (const std::string& n : rep.nondeterministic_first) md += "- " + md_cell(n) + "\n";
  }
  if (!rep.ratios.empty()) {
    md += fmt::format("\nPoints added, ours / theirs on the same input and theta (runs both finished; {} comparison runs, {} from "
                      "the cache{}):\n\n",
                      rep.comparison_runs, rep.comparison_cache_hits,
                      rep.points_cache_dir.empty() ? "" : " in " + rep.points_cache_dir);
    md += "| against | runs | median | min | max | total |\n|---|---:|---:|---:|---:|---:|\n";
    for (const PointsRatio& p : rep.ratios)
      md += fmt::format("| {} | {} | {:.3f} | {:.3f} | {:.3f} | {:.3f} |\n", p.against, p.cases, p.median, p.min, p.max, p.total);
  }
  md += format_order_terminations(rep.order_terminations, 20);
  bool any = false;
  for (const RowSummary& r : rep.rows)
    for (const Counterexample& c : r.counterexamples) {
      if (!any) md += "\n## Findings\n\n";
      any = true;
      if (c.shrink_steps > 0) {
        md += fmt::format("- **{}** theta {}: {} ({} vertices, {} segments, {} holes, shrunk from {} vertices, {} segments, {} holes; "
                          "{} shrink steps in {} runs, each failing with {}; from {})\n",
                          row_key(c.row), theta_text(c.theta), md_cell(c.detail), c.vertices, c.segments, c.holes,
                          c.original_vertices, c.original_segments, c.original_holes, c.shrink_steps, c.shrink_runs,
                          c.signature, c.input);
        md += fmt::format("  as found: {}\n", md_cell(c.original_detail));
      } else {
        md += fmt::format("- **{}** theta {}: {} ({} vertices, {} segments, {} holes, as found{}; from {})\n", row_key(c.row),
                          theta_text(c.theta), md_cell(c.detail), c.vertices, c.segments, c.holes,
                          c.shrink_runs > 0 ? fmt::format(": no smaller input failed with {} in {} runs", c.signature, c.shrink_runs)
                                            : "",
                          c.input);
      }
      if (!c.deterministic) md += fmt::format("  **not deterministic**: {}\n", md_cell(c.nondeterminism));
      md += fmt::format("  files: `{}/`", c.dir);
      if (!c.reproduce.empty())
        md += fmt::format("; reproduce{}: `{}`", c.deterministic ? "" : " (may not reproduce: not deterministic)", c.reproduce);
      md += "\n";
    }
  if (!rep.internal_errors.empty()) {
    md += "\n## Internal errors of the audit\n\n";
    for (const Counterexample& c : rep.internal_errors) {
      md += fmt::format("- **internal-error** ({}) theta {}: {} ({} vertices, {} segments, {} holes, {}; from {})\n", row_key(c.row),
                        theta_text(c.theta), md_cell(c.detail), c.vertices, c.segments, c.holes,
                        c.shrink_steps > 0 ? fmt::format("shrunk from {} vertices in {} steps", c.original_vertices, c.shrink_steps)
                                           : std::string("as found"),
                        c.input);
      md += fmt::format("  files: `{}/`", c.dir);
      if (!c.reproduce.empty()) md += fmt::format("; reproduce: `{}`", c.reproduce);
      md += "\n";
    }
  }
  if (!rep.skipped_inputs.empty()) {
    md += fmt::format("\n{} inputs skipped (missing, unreadable or invalid)", rep.skipped_inputs.size());
    md += rep.skipped_inputs.size() <= 5 ? ":\n" : ", the first 5:\n";
    for (std::size_t i = 0; i < rep.skipped_inputs.size() && i < 5; ++i) md += "- " + md_cell(rep.skipped_inputs[i]) + "\n";
  }
  bool failed = false;
  for (const RowSummary& r : rep.rows) failed = failed || !r.holds();
  std::string verdict = failed ? "some rows FAILED" : "every row holds";
  if (rep.internal_error_runs > 0)
    verdict = fmt::format("the audit itself FAILED on {} runs (internal errors, those runs undecided); on the others, {}",
                          rep.internal_error_runs, failed ? "some rows FAILED" : "every row holds");
  md += fmt::format("\nVerdict: {}.\n", verdict);
  return md;
}

nlohmann::json json_report(const AuditReport& rep) {
  auto counterexample = [](const Counterexample& c) {
    nlohmann::json j = {{"dir", c.dir},
                        {"input", c.input},
                        {"theta", c.theta},
                        {"vertices", c.vertices},
                        {"segments", c.segments},
                        {"holes", c.holes},
                        {"original_vertices", c.original_vertices},
                        {"original_segments", c.original_segments},
                        {"original_holes", c.original_holes},
                        {"shrink_steps", c.shrink_steps},
                        {"shrink_runs", c.shrink_runs},
                        {"shrink_timeout", c.shrink_timeout},
                        {"signature", c.signature},
                        {"detail", c.detail},
                        {"original_detail", c.original_detail},
                        {"original_input", c.original_input},
                        {"deterministic", c.deterministic},
                        {"nondeterminism", c.nondeterminism},
                        {"stderr_file", c.stderr_file},
                        {"reproduce", c.reproduce}};
    if (!c.deviation.empty()) j["deviation"] = c.deviation;
    if (!c.deviations.empty()) j["deviations"] = deviations_json(c.deviations);
    if (!c.chain_end_reason.empty()) j["chain_end_reason"] = c.chain_end_reason;
    if (!c.mesh_reading.empty()) j["mesh_reading"] = c.mesh_reading;
    return j;
  };
  nlohmann::json rows = nlohmann::json::array();
  for (const RowSummary& r : rep.rows) {
    nlohmann::json cx = nlohmann::json::array();
    for (const Counterexample& c : r.counterexamples) cx.push_back(counterexample(c));
    rows.push_back({{"check", row_key(r.row)},
                    {"statement", row_statement(r.row)},
                    {"paper", row_passage(r.row)},
                    {"runs", r.run},
                    {"held", r.held},
                    {"failed", r.failed},
                    {"findings", r.findings},
                    {"not_applicable", r.not_applicable},
                    {"not_checked", r.not_checked},
                    {"internal_errors", r.internal_errors},
                    {"holds", r.holds()},
                    {"first", r.first_detail},
                    {"deviations", r.deviations},
                    {"deviations_consistent", r.deviation_consistent},
                    {"inexact_runs", r.inexact_runs},
                    {"inexact_steps", r.inexact_steps},
                    {"counterexamples", cx}});
  }
  nlohmann::json internal = nlohmann::json::array();
  for (const Counterexample& c : rep.internal_errors) {
    internal.push_back(counterexample(c));
    internal.back()["check"] = row_key(c.row);
  }
  nlohmann::json ratios = nlohmann::json::array();
  for (const PointsRatio& p : rep.ratios)
    ratios.push_back({{"against", p.against}, {"runs", p.cases}, {"median", p.median}, {"min", p.min}, {"max", p.max}, {"total", p.total}});
  nlohmann::json statuses = nlohmann::json::object();
  for (int s = 0; s < 6; ++s) statuses[to_string(static_cast<RunStatus>(s))] = rep.status_counts[s];
  nlohmann::json j = {{"engine", rep.engine},
                      {"method", to_string(rep.method)},
                      {"thetas", rep.thetas},
                      {"seed", rep.seed},
                      {"inputs", rep.inputs},
                      {"runs", rep.cases},
                      {"holds", rep.holds()},
                      {"rows", rows},
                      {"internal_error_runs", rep.internal_error_runs},
                      {"internal_errors", internal},
                      {"centroid", rep.area_centroid ? "area" : "vertex"},
                      {"arithmetic", rep.arithmetic_double ? "double" : "exact"},
                      {"tie_search_states", rep.tie_search_states},
                      {"points_ratio", ratios},
                      {"order_termination", to_json(rep.order_terminations)},
                      {"run_status", statuses},
                      {"exempt_triangles", rep.exempt_triangles},
                      {"runs_with_exempt_triangles", rep.runs_with_exempt},
                      {"precision_exempt_triangles", rep.precision_exempt_triangles},
                      {"runs_with_precision_exempt_triangles", rep.runs_with_precision_exempt},
                      {"skipped_inputs", rep.skipped_inputs},
                      {"jobs", rep.jobs},
                      {"repeat", rep.repeat},
                      {"nondeterministic_cases", rep.nondeterministic_cases},
                      {"nondeterministic_first", rep.nondeterministic_first},
                      {"comparison_runs", rep.comparison_runs},
                      {"comparison_cache_hits", rep.comparison_cache_hits},
                      {"points_cache_dir", rep.points_cache_dir},
                      {"seconds", rep.seconds},
                      {"engine_seconds", rep.engine_seconds},
                      {"comparison_seconds", rep.comparison_seconds},
                      {"shrink_seconds", rep.shrink_seconds},
                      {"overhead_per_run_ms", rep.overhead_per_case_ms},
                      {"out_dir", rep.out_dir}};
  if (rep.shard) j["shard"] = shard_to_json(rep);
  return j;
}

std::string junit_report(const AuditReport& rep) {
  std::size_t failures = 0, errors = 0;
  for (const RowSummary& r : rep.rows) failures += r.failed > 0, errors += r.failed == 0 && r.internal_errors > 0;
  std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  x += fmt::format("<testsuites name=\"lepp audit\" tests=\"{}\" failures=\"{}\" errors=\"{}\" time=\"{:.3f}\">\n", kRows, failures,
                   errors, rep.seconds);
  x += fmt::format("  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"{}\" time=\"{:.3f}\">\n",
                   xml_escape(fmt::format("lepp audit {} {} theta {}", rep.engine, to_string(rep.method), thetas_text(rep.thetas))),
                   kRows, failures, errors, rep.seconds);
  for (const RowSummary& r : rep.rows) {
    x += fmt::format("    <testcase classname=\"lepp.audit.{}\" name=\"{}\">\n", xml_escape(rep.engine), row_key(r.row));
    if (r.failed > 0) {
      std::string body = fmt::format("{} of {} runs failed. {}\nPaper: {}\n", r.failed, r.run, r.first_detail, row_passage(r.row));
      for (const auto& [name, runs] : r.deviations) body += fmt::format("deviation {}: {} runs\n", name, runs);
      for (const Counterexample& c : r.counterexamples)
        body += fmt::format("{}: {} ({} vertices): {}\n{}\n", c.shrink_steps > 0 ? "shrunk" : "as found", c.dir, c.vertices, c.detail, c.reproduce);
      x += fmt::format("      <failure message=\"{}\">{}</failure>\n", xml_escape(row_statement(r.row)), xml_escape(body));
    } else if (r.internal_errors > 0) {
      // JUnit's <error>: the check itself broke, the runs are undecided.
      std::string body = fmt::format("the audit's own verdict code stopped on {} runs (internal errors of lepp audit)\n", r.internal_errors);
      for (const Counterexample& c : rep.internal_errors)
        if (c.row == r.row) body += fmt::format("{}: {}\n{}\n", c.dir, c.detail, c.reproduce);
      x += fmt::format("      <error message=\"internal error of lepp audit\">{}</error>\n", xml_escape(body));
    } else if (r.run == 0) {
      x += "      <skipped message=\"no run this check applied to\"/>\n";
    }
    x += fmt::format("      <system-out>{}</system-out>\n",
                     xml_escape(fmt::format("runs {}, held {}, failed {}, findings {}, n/a {}, not checked {}", r.run, r.held,
                                            r.failed, r.findings, r.not_applicable, r.not_checked)));
    x += "    </testcase>\n";
  }
  x += "  </testsuite>\n</testsuites>\n";
  return x;
}

}  // namespace lepp::audit
