// SPDX-License-Identifier: GPL-3.0-or-later
// The audit's HTML page (lepp/audit/report/html.h): the summary, the rows, the
// deviations by name, the findings (html_findings.cpp), the comparisons.
#include "lepp/audit/report/html.h"

#include <fstream>

#include <fmt/format.h>

#include "html_findings.h"
#include "row_verdict.h"
#include "lepp/audit/report/report.h"
#include "lepp/audit/theta_text.h"
#include "lepp/html/page.h"

namespace lepp::audit {
namespace {

using html::escape;

std::string summary(const AuditReport& rep) {
  const std::string thetas = thetas_text(rep.thetas);
  std::string out = fmt::format("<p>Method {}, theta {}; {} runs on {} inputs (seed {}{}); {:.1f} s with -j {}, of which the engine {:.1f} s.</p>\n",
                                to_string(rep.method), thetas, rep.cases, rep.inputs, rep.seed,
                                rep.repeat > 1 ? fmt::format(", each case run {} times", rep.repeat) : "", rep.seconds, rep.jobs,
                                rep.engine_seconds);
  if (rep.shard)
    out += fmt::format("<p>Shard {} of {}: {} of the audit's {} cases (<code>lepp audit merge</code> makes the whole report).</p>\n",
                       rep.shard->index, rep.shard->count, rep.shard->cases.size(), rep.shard->total_cases);
  bool failed = false;
  for (const RowSummary& r : rep.rows) failed = failed || !r.holds();
  std::string verdict = failed ? "Some rows FAILED." : "Every row holds.";
  if (rep.internal_error_runs > 0)
    verdict = fmt::format("The audit itself failed on {} runs (internal errors, those runs undecided); on the others, {}",
                          rep.internal_error_runs, failed ? "some rows FAILED." : "every row holds.");
  out += fmt::format("<p id=\"verdict\" class=\"verdict {}\" data-holds=\"{}\">{}</p>\n", rep.holds() ? "ok" : "bad",
                     rep.holds() ? "true" : "false", verdict);
  return out;
}

std::string rows_table(const AuditReport& rep) {
  std::string out =
      "<table id=\"rows\"><thead><tr><th>#</th><th>check</th><th>statement (paper)</th><th class=\"n\">runs</th><th class=\"n\">held</th>"
      "<th class=\"n\">failed</th><th>verdict</th><th>smallest counterexample</th></tr></thead><tbody>\n";
  for (std::size_t i = 0; i < kRows; ++i) {
    const RowSummary& r = rep.rows[i];
    std::string smallest;
    if (!r.counterexamples.empty()) {
      const Counterexample& c = r.counterexamples.front();
      smallest = fmt::format("<a href=\"#{}\">{}</a> ({} vertices, {} segments)", escape(detail::finding_anchor(c)), escape(c.dir),
                             c.vertices, c.segments);
    } else if (!r.first_detail.empty()) {
      smallest = escape(r.first_detail);
    }
    out += fmt::format(
        "<tr data-row=\"{0}\" data-runs=\"{2}\" data-held=\"{3}\" data-failed=\"{4}\" data-findings=\"{5}\"><td>{1}</td><td>{0}</td>"
        "<td>{6} <i>({7})</i></td><td class=\"n\">{2}</td><td class=\"n\">{3}</td><td class=\"n\">{4}{8}</td><td class=\"{9}\">{10}</td><td>{11}</td></tr>\n",
        row_key(r.row), i + 1, r.run, r.held, r.failed, r.findings, escape(row_statement(r.row)), escape(row_passage(r.row)),
        r.findings ? fmt::format(" (+{} findings)", r.findings) : "", r.failed ? "bad" : "ok", escape(detail::row_verdict(r)), smallest);
  }
  out += "</tbody></table>\n";
  out += "<p>Runs a row did not apply to:";
  for (std::size_t i = 0; i < kRows; ++i)
    out += fmt::format("{} {} {} n/a, {} not checked", i ? ";" : "", row_key(rep.rows[i].row), rep.rows[i].not_applicable,
                       rep.rows[i].not_checked);
  return out + ".</p>\n";
}

// The deviations of each row by name: runs, where first seen, and the first saved finding that shows it.
std::string deviations_table(const AuditReport& rep) {
  std::string body;
  for (const RowSummary& r : rep.rows)
    for (const auto& [name, runs] : r.deviations) {
      std::string link;
      for (const Counterexample& c : r.counterexamples)
        for (const DeviationLink& d : c.deviations)
          if (link.empty() && d.deviation == name)
            link = fmt::format("<a href=\"#{}-step\">step {} of {}</a>", escape(detail::finding_anchor(c)), d.first_step, escape(c.dir));
      if (link.empty())
        for (const Counterexample& c : r.counterexamples)
          if (link.empty() && c.deviation == name) link = fmt::format("<a href=\"#{0}\">{0}</a>", escape(detail::finding_anchor(c)));
      const auto first = r.deviation_first.find(name);
      const auto consistent = r.deviation_consistent.find(name);
      body += fmt::format("<tr data-row=\"{0}\" data-deviation=\"{1}\" data-count=\"{2}\"><td>{0}</td><td><b>{1}</b></td><td class=\"n\">{2}</td>"
                          "<td class=\"n\">{3}</td><td>{4}</td><td>{5}</td></tr>\n",
                          row_key(r.row), escape(name), runs, consistent != r.deviation_consistent.end() ? consistent->second : 0,
                          first != r.deviation_first.end() ? escape(first->second) : "", link);
    }
  if (body.empty()) return "<p id=\"no-deviations\">No deviation named.</p>\n";
  return "<table id=\"deviations\"><thead><tr><th>row</th><th>deviation</th><th class=\"n\">runs</th><th class=\"n\">consistent runs</th>"
         "<th>first seen</th><th>first saved finding</th></tr></thead><tbody>\n" +
         body + "</tbody></table>\n";
}

std::string comparisons(const AuditReport& rep) {
  std::string out = "<p>How the runs ended:";
  bool first = true;
  for (int s = 0; s < 6; ++s)
    if (rep.status_counts[s]) out += fmt::format("{} {} {}", first ? "" : ",", to_string(static_cast<RunStatus>(s)), rep.status_counts[s]), first = false;
  out += ".</p>\n";
  if (rep.nondeterministic_cases > 0) {
    out += fmt::format("<p class=\"bad\">Not deterministic: in {} cases the repeated runs gave different outputs.</p>\n<ul>\n",
                       rep.nondeterministic_cases);
    for (const std::string& n : rep.nondeterministic_first) out += "<li>" + escape(n) + "</li>\n";
    out += "</ul>\n";
  }
  if (!rep.ratios.empty()) {
    out += "<table id=\"ratios\"><thead><tr><th>points added, ours / theirs, against</th><th class=\"n\">runs</th><th class=\"n\">median</th>"
           "<th class=\"n\">min</th><th class=\"n\">max</th><th class=\"n\">total</th></tr></thead><tbody>\n";
    for (const PointsRatio& p : rep.ratios)
      out += fmt::format("<tr><td>{}</td><td class=\"n\">{}</td><td class=\"n\">{:.3f}</td><td class=\"n\">{:.3f}</td><td class=\"n\">{:.3f}</td><td class=\"n\">{:.3f}</td></tr>\n",
                         escape(p.against), p.cases, p.median, p.min, p.max, p.total);
    out += "</tbody></table>\n";
  }
  if (!rep.skipped_inputs.empty()) {
    out += fmt::format("<p>{} inputs skipped (missing, unreadable or invalid):</p>\n<ul>\n", rep.skipped_inputs.size());
    for (std::size_t i = 0; i < rep.skipped_inputs.size() && i < 5; ++i) out += "<li>" + escape(rep.skipped_inputs[i]) + "</li>\n";
    out += "</ul>\n";
  }
  return out;
}

}  // namespace

std::string html_report(const AuditReport& rep) {
  html::Page page("lepp audit: " + rep.engine);
  page.add("<h1>Audit: " + escape(rep.engine) + "</h1>\n");
  page.add(summary(rep));
  page.add("<h2>The paper's statements</h2>\n" + rows_table(rep));
  page.add("<h2>Deviations by name</h2>\n" + deviations_table(rep));
  page.add("<pre class=\"readings\">" + escape(deviations_text(rep)) + "</pre>\n");
  std::string findings;
  for (const RowSummary& r : rep.rows)
    for (const Counterexample& c : r.counterexamples) findings += detail::finding_section(page, c, false);
  if (!findings.empty()) page.add("<h2>Findings</h2>\n" + findings);
  std::string internal;
  for (const Counterexample& c : rep.internal_errors) internal += detail::finding_section(page, c, true);
  if (!internal.empty()) page.add("<h2>Internal errors of the audit</h2>\n" + internal);
  page.add("<h2>Runs</h2>\n" + comparisons(rep));
  return page.str();
}

std::string write_html_report(const AuditReport& report, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  out << html_report(report);
  return out.flush() ? std::string() : "cannot write " + path;
}

}  // namespace lepp::audit
