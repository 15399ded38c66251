// SPDX-License-Identifier: GPL-3.0-or-later
// A finding on the audit's HTML page: its words, its pictures from its directory, its reproduce command.
#include <filesystem>
#include <optional>

#include <fmt/format.h>

#include "html_findings.h"
#include "lepp/audit/report/finding.h"
#include "lepp/audit/theta_text.h"
#include "lepp/input.h"

namespace fs = std::filesystem;

namespace lepp::audit::detail {
namespace {

using html::escape;

// The picture of one SVG file of the finding's directory, or nothing when it is not there.
std::string picture(html::Page& page, const fs::path& file, const std::string& caption, const char* css_class) {
  const auto svg = html::file_bytes(file.string());
  if (!svg || svg->find("<svg") == std::string::npos) return {};
  return page.figure(*svg, caption, css_class);
}

// The shrunk input (input.poly) drawn with the finding's plain drawing: its segments, no mesh.
std::string input_picture(html::Page& page, const fs::path& dir, const Counterexample& c) {
  try {
    std::vector<std::string> warnings;
    const Pslg input = read_poly((dir / "input.poly").string(), warnings);
    if (input.vertices.empty()) return {};
    return page.figure(finding_svg(input, nullptr, RowResult{}, fmt::format("input.poly: {} vertices, {} segments", c.vertices, c.segments)),
                       c.shrink_steps > 0 ? "The shrunk input" : "The input", "step");
  } catch (const std::exception& e) {
    return "<p class=\"bad no-picture\">no picture of input.poly: " + escape(e.what()) + "</p>\n";
  }
}

}  // namespace

std::string finding_anchor(const Counterexample& c) { return "finding-" + fs::path(c.dir).filename().string(); }

std::string finding_section(html::Page& page, const Counterexample& c, bool internal) {
  const std::string anchor = finding_anchor(c);
  std::string out = fmt::format("<section class=\"finding\" id=\"{}\" data-row=\"{}\"{}>\n", escape(anchor), row_key(c.row),
                                internal ? " data-internal=\"true\"" : "");
  out += fmt::format("<h3>{}{} theta {}: {}</h3>\n", internal ? "internal error of the audit in " : "", row_key(c.row),
                     theta_text(c.theta), escape(c.detail));
  out += "<ul>\n";
  out += "<li>from <code>" + escape(c.input) + "</code>; " +
         (c.shrink_steps > 0
              ? fmt::format("shrunk to {} vertices, {} segments, {} holes from {} vertices, {} segments, {} holes in {} steps "
                            "({} runs), each failing with <code>{}</code>",
                            c.vertices, c.segments, c.holes, c.original_vertices, c.original_segments, c.original_holes,
                            c.shrink_steps, c.shrink_runs, escape(c.signature))
              : fmt::format("as found: {} vertices, {} segments, {} holes", c.vertices, c.segments, c.holes)) +
         "</li>\n";
  if (c.shrink_steps > 0 && !c.original_detail.empty()) out += "<li>as found: " + escape(c.original_detail) + "</li>\n";
  for (const DeviationLink& d : c.deviations)
    out += fmt::format("<li class=\"deviation\" data-deviation=\"{0}\">deviation <b>{0}</b> from <a href=\"#{1}-step\">step {2}</a>{3}</li>\n",
                       escape(d.deviation), escape(anchor), d.first_step,
                       d.steps > 0 ? fmt::format(", {} step{} replayed with it", d.steps, d.steps == 1 ? "" : "s") : "");
  if (!c.deterministic) out += "<li class=\"bad\">not deterministic: " + escape(c.nondeterminism) + "</li>\n";
  out += "<li>files: <code>" + escape(c.dir) + "/</code></li>\n</ul>\n";
  const fs::path dir(c.dir);
  const std::string step = picture(page, dir / "step.svg",
                                   "The step: the mesh just before it, the paper's choice and the program's point", "step");
  // The deviations' links lead here, picture or not.
  out += "<div id=\"" + escape(anchor) + "-step\">" +
         (step.empty() && !c.deviations.empty() ? std::string("<p>no picture of the step (no step.svg in the directory)</p>") : step) +
         "</div>\n";
  out += picture(page, dir / "chain-end.svg",
                 "Where the chain of deviations stopped: the mesh just before that step, the nearest choices and the program's point",
                 "step");
  out += input_picture(page, dir, c);
  out += picture(page, dir / "finding-zoom.svg", "The program's mesh around the violation", "step");
  std::string whole = picture(page, dir / "finding.svg", "The program's whole mesh, the violation in red", "step");
  if (!whole.empty()) out += html::details("the whole mesh", whole);
  if (!c.reproduce.empty()) {
    const std::string id = escape(anchor) + "-reproduce";
    out += fmt::format("<p>reproduce{}: <button class=\"copy\" data-copy=\"{}\">copy</button></p><pre id=\"{}\">{}</pre>\n",
                       c.deterministic ? "" : " (may not reproduce: not deterministic)", id, id, escape(c.reproduce));
  }
  return out + "</section>\n";
}

}  // namespace lepp::audit::detail
