// SPDX-License-Identifier: GPL-3.0-or-later
// A finding on disk: the input, the program's output, the picture, reproduce.sh and finding.md.
#include "lepp/audit/report/finding.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>

#include <fmt/format.h>

#include "lepp/audit/judge/diagnosis.h"
#include "lepp/certify_svg.h"
#include "lepp/io.h"
#include "lepp/render.h"
#include "loop/scratch_names.h"
#include "xml_escape.h"

namespace fs = std::filesystem;

namespace lepp::audit {
namespace {

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

}  // namespace

std::string finding_svg(const Pslg& input, const Mesh* mesh, const RowResult& result, const std::string& title) {
  double min_x = INFINITY, min_y = INFINITY, max_x = -INFINITY, max_y = -INFINITY;
  auto grow = [&](const Point& p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
    min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
    min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
  };
  for (const Point& p : input.vertices) grow(p);
  if (!(max_x >= min_x)) min_x = min_y = 0, max_x = max_y = 1;
  const double size = 800, margin = 20;
  const double span = std::max({max_x - min_x, max_y - min_y, 1e-300});
  const double scale = size / span;
  auto X = [&](double x) { return margin + (x - min_x) * scale; };
  auto Y = [&](double y) { return margin + (max_y - y) * scale; };
  const double w = (max_x - min_x) * scale + 2 * margin, h = (max_y - min_y) * scale + 2 * margin + 30;
  std::string s = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" viewBox=\"0 0 {:.1f} {:.1f}\">\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      w, h, w, h);
  auto valid = [&](int v) { return mesh && v >= 0 && static_cast<std::size_t>(v) < mesh->vertices.size(); };
  auto P = [&](int v) { return mesh->vertices[static_cast<std::size_t>(v)]; };
  if (mesh) {
    std::string d;
    for (const Tri& t : mesh->triangles) {
      if (!valid(t[0]) || !valid(t[1]) || !valid(t[2])) continue;
      d += fmt::format("M{:.1f} {:.1f}L{:.1f} {:.1f}L{:.1f} {:.1f}Z", X(P(t[0]).x), Y(P(t[0]).y), X(P(t[1]).x), Y(P(t[1]).y),
                       X(P(t[2]).x), Y(P(t[2]).y));
    }
    s += "<path fill=\"#eef3fb\" stroke=\"#7a8aa0\" stroke-width=\"0.5\" d=\"" + d + "\"/>\n";
  }
  // Input segments bold: what must be kept.
  std::string seg;
  for (const Segment& g : input.segments) {
    const Point &a = input.vertices[static_cast<std::size_t>(g.a)], &b = input.vertices[static_cast<std::size_t>(g.b)];
    seg += fmt::format("M{:.1f} {:.1f}L{:.1f} {:.1f}", X(a.x), Y(a.y), X(b.x), Y(b.y));
  }
  s += "<path fill=\"none\" stroke=\"black\" stroke-width=\"2\" d=\"" + seg + "\"/>\n";
  // The violation, red.
  for (const certify::Violation& v : result.violations) {
    for (int ti : v.triangles) {
      if (!mesh || ti < 0 || static_cast<std::size_t>(ti) >= mesh->triangles.size()) continue;
      const Tri& t = mesh->triangles[static_cast<std::size_t>(ti)];
      if (!valid(t[0]) || !valid(t[1]) || !valid(t[2])) continue;
      s += fmt::format("<path fill=\"#ff000060\" stroke=\"red\" stroke-width=\"1.5\" d=\"M{:.1f} {:.1f}L{:.1f} {:.1f}L{:.1f} {:.1f}Z\"/>\n",
                       X(P(t[0]).x), Y(P(t[0]).y), X(P(t[1]).x), Y(P(t[1]).y), X(P(t[2]).x), Y(P(t[2]).y));
    }
    for (const auto& e : v.edges)
      if (valid(e[0]) && valid(e[1]))
        s += fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"red\" stroke-width=\"3\"/>\n",
                         X(P(e[0]).x), Y(P(e[0]).y), X(P(e[1]).x), Y(P(e[1]).y));
    for (const Point& p : v.points)
      if (std::isfinite(p.x) && std::isfinite(p.y))
        s += fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"5\" fill=\"none\" stroke=\"red\" stroke-width=\"2\"/>\n", X(p.x), Y(p.y));
  }
  s += fmt::format("<text x=\"{:.0f}\" y=\"{:.0f}\" font-family=\"sans-serif\" font-size=\"13\">{}</text>\n", margin,
                   h - 10, detail::xml_escape(title));
  s += "</svg>\n";
  return s;
}

void save_finding(const std::string& dir, Row row, const Pslg& input, const EngineRun& run, const RowResult& result,
                  const FindingText& text) {
  fs::create_directories(dir);
  const fs::path d(dir);
  write_poly((d / "input.poly").string(), input);
  if (!run.output_files.empty()) {
    for (const std::string& f : run.output_files) {
      std::error_code ec;
      fs::copy_file(f, d / ("out" + fs::path(f).extension().string()), fs::copy_options::overwrite_existing, ec);
    }
  } else if (!run.mesh.triangles.empty()) {
    try {
      write_mesh((d / "out").string(), run.mesh);
    } catch (const std::exception&) {
    }
    if (run.trace) {
      std::ofstream t(d / "out.trace");
      t << "# Steiner points in insertion order: x y\n";
      for (const Point& p : *run.trace) t << fmt::format("{:.17g} {:.17g}\n", p.x, p.y);
    }
  }
  if (!run.stderr_text.empty()) write_text(d / "stderr.txt", run.stderr_text);
  const Mesh* mesh = run.status == RunStatus::Ok || !run.mesh.triangles.empty() ? &run.mesh : nullptr;
  std::string title = fmt::format("{} {} theta {}: {} {}", text.engine, to_string(text.method), text.theta, row_key(row),
                                  result.detail.substr(0, 160));
  // The mesh with lepp::render (the whole, and a window around the violation);
  // without a mesh, or if it cannot draw it, the input alone.
  bool drawn = false;
  if (mesh && !mesh->triangles.empty()) {
    try {
      render::RenderOptions ro;
      ro.color = render::ColorBy::Angle;
      ro.highlight_bad = row == Row::MinAngle;
      ro.min_angle_deg = text.theta;
      ro.title = title;
      render::Highlight h = certify::highlight_of(result.violations, *mesh);
      h.label = row_key(row);
      ro.highlights.push_back(h);
      write_text(d / "finding.svg", render::render_svg(*mesh, ro));
      drawn = true;
      if (!h.triangles.empty() || !h.points.empty()) {
        ro.window = render::window_around(*mesh, h.triangles, h.points);
        write_text(d / "finding-zoom.svg", render::render_svg(*mesh, ro));
      }
    } catch (const std::exception&) {
      // a mesh the renderer refuses (ids out of range): the plain drawing below
    }
  }
  if (!drawn) write_text(d / "finding.svg", finding_svg(input, mesh, result, title));
  if (!text.reproduce.empty()) {
    std::string sh = "#!/bin/sh\n";
    if (!text.nondeterminism.empty())
      sh += "# WARNING: the program is not deterministic (" + text.nondeterminism +
            "): this may not reproduce the finding.\n"
            "echo 'warning: the audited program is not deterministic: this may not reproduce the finding' >&2\n";
    write_text(d / "reproduce.sh", sh + text.reproduce + "\n");
  }
  // The program's files by their names here (out.node, ...: this run's are copied
  // beside finding.md), not by the audit's run directory, gone when the audit ends
  // (loop/scratch_names.h).
  auto saved = [](const std::string& words) { return std::regex_replace(words, loop::run_dir_pattern(), ""); };
  std::string md = fmt::format(
      "# {}: {}\n\n- engine: {}\n- method: {}, theta: {}\n- statement: {}\n- paper: {}\n- verdict: {}\n- run: {}{}\n",
      row_key(row), to_string(result.verdict), text.engine, to_string(text.method), text.theta, row_statement(row),
      row_passage(row), saved(result.detail), to_string(run.status), run.detail.empty() ? "" : " (" + saved(run.detail) + ")");
  if (result.verdict == Verdict::InternalError)
    md += fmt::format("- **an internal error of lepp audit, not a failure of the program**: the audit's {} stopped on this run, "
                      "so the row is undecided. Please report it with this directory (input.poly and the program's output "
                      "are here; the reproduce line runs the same check again).\n",
                      result.internal_error);
  const std::string sizes = fmt::format("{} vertices, {} segments, {} holes", input.vertices.size(), input.segments.size(),
                                        input.holes.size());
  if (text.shrink_steps > 0) {
    md += fmt::format("- input: input.poly ({}), shrunk in {} steps from {} ({} vertices, {} segments, {} holes)\n", sizes,
                      text.shrink_steps, text.input_origin, text.original_vertices, text.original_segments, text.original_holes);
    if (!text.original_detail.empty()) md += "- as found, before shrinking: " + saved(text.original_detail) + "\n";
  } else {
    md += fmt::format("- input: input.poly ({}), as found: {} ({})\n", sizes, text.input_origin,
                      text.shrink_tried ? "no smaller input failed the same way" : "not shrunk: --no-shrink");
  }
  if (!text.signature.empty() && text.shrink_tried) md += "- kept while shrinking: the same row failing with " + text.signature + "\n";
  if (!text.nondeterminism.empty())
    md += "- **the program is not deterministic**: " + text.nondeterminism + "; the counterexample may not reproduce\n";
  if (!text.reproduce.empty())
    md += std::string("- reproduce") + (text.nondeterminism.empty() ? "" : " (may not reproduce: not deterministic)") + ": `" +
          text.reproduce + "`\n";
  // The program's stderr as kept (its first 64 KiB), not only a line of it: an exception is often the last line.
  if (!run.stderr_text.empty()) {
    constexpr std::size_t kShown = 16 * 1024;
    const std::string& all = run.stderr_text;
    std::string shown = all.size() > kShown ? "...\n" + all.substr(all.size() - kShown) : all;
    for (std::size_t at = 0; (at = shown.find("```", at)) != std::string::npos;) shown.replace(at, 3, "'''");
    if (shown.back() != '\n') shown += '\n';
    md += fmt::format("\n## The program's stderr ({} bytes{}; all of it in stderr.txt)\n\n```\n{}```\n", all.size(),
                      all.size() > kShown ? fmt::format(", the last {} here", kShown) : "", shown);
  }
  // A step finding: the mesh just before the step, and the named deviation.
  if (result.diagnosis) {
    md += diagnosis_markdown(*result.diagnosis);
    try {
      write_text(d / "step.svg", diagnosis_svg(*result.diagnosis, fmt::format("{} step {}", row_key(row), result.diagnosis->step())));
    } catch (const std::exception& e) {
      md += fmt::format("\n(step.svg not drawn: {})\n", e.what());
    }
    // The step where the chain stopped at no rule (issue 42): its own picture, so a
    // reader can see which rule the point misses and add one.
    if (const auto& end = result.diagnosis->chain_end) {
      std::string words = diagnosis_markdown(*end);
      const std::string heading = "## The step (step.svg)";
      if (const std::size_t at = words.find(heading); at != std::string::npos)
        words.replace(at, heading.size(), "## Where the chain stopped (chain-end.svg)");
      md += words;
      try {
        write_text(d / "chain-end.svg", diagnosis_svg(*end, fmt::format("{} step {}: the chain stopped", row_key(row), end->step())));
      } catch (const std::exception& e) {
        md += fmt::format("\n(chain-end.svg not drawn: {})\n", e.what());
      }
    }
  }
  write_text(d / "finding.md", md);
}

}  // namespace lepp::audit
