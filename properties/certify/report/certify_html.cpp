// SPDX-License-Identifier: GPL-3.0-or-later
// A certificate's HTML page (lepp/certify_html.h): the parts in reading order. The
// pictures are certify_overview.cpp's and certify_zoom.cpp's; the skeleton is lepp::html.
#include "lepp/certify_html.h"

#include <algorithm>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

#include "certify_pictures.h"
#include "lepp/html/histogram.h"
#include "lepp/html/page.h"
#include "lepp/stats.h"

namespace lepp::certify {
namespace {

using html::escape;

std::string row(std::initializer_list<std::string> cells, const std::string& attributes = "") {
  std::string out = "<tr" + attributes + ">";
  bool first = true;
  for (const std::string& c : cells) {
    out += first ? "<td>" : "<td class=\"n\">";
    out += c;
    out += "</td>";
    first = false;
  }
  return out + "</tr>\n";
}

std::string coordinate(const Point& p) { return fmt::format("({:.17g}, {:.17g})", p.x, p.y); }

bool valid_vertex(const Mesh& mesh, int v) { return v >= 0 && static_cast<std::size_t>(v) < mesh.vertices.size(); }

// The exact coordinates of what a violation names: its triangles' corners, its edges' ends, its points.
std::string coordinates(const Mesh& mesh, const Violation& v) {
  std::string out;
  for (int t : v.triangles) {
    if (t < 0 || static_cast<std::size_t>(t) >= mesh.triangles.size()) continue;
    out += fmt::format("triangle {}:", t);
    for (int id : mesh.triangles[static_cast<std::size_t>(t)])
      out += valid_vertex(mesh, id) ? fmt::format(" v{} {}", id, coordinate(mesh.vertices[static_cast<std::size_t>(id)]))
                                    : fmt::format(" v{} (no such vertex)", id);
    out += "\n";
  }
  for (const auto& e : v.edges)
    if (valid_vertex(mesh, e[0]) && valid_vertex(mesh, e[1]))
      out += fmt::format("edge v{} {} - v{} {}\n", e[0], coordinate(mesh.vertices[static_cast<std::size_t>(e[0])]), e[1],
                         coordinate(mesh.vertices[static_cast<std::size_t>(e[1])]));
  for (const Point& p : v.points) out += "point " + coordinate(p) + "\n";
  return out;
}

std::string verdict(const Report& report) {
  std::size_t total = 0, kinds = 0;
  for (std::size_t c : report.count_by_reason) total += c, kinds += c > 0;
  if (report.certified())
    return "<p id=\"verdict\" class=\"verdict ok\" data-certified=\"true\" data-violations=\"0\">Certified: every check passed.</p>\n";
  return fmt::format(
      "<p id=\"verdict\" class=\"verdict bad\" data-certified=\"false\" data-violations=\"{0}\">Not certified: {0} violation{1} of "
      "{2} kind{3}.</p>\n",
      total, total == 1 ? "" : "s", kinds, kinds == 1 ? "" : "s");
}

std::string counts_table(const Report& report) {
  std::map<Reason, std::size_t> listed;
  for (const Violation& v : report.violations) ++listed[v.reason];
  std::string out = "<table id=\"counts\"><thead><tr><th>check</th><th>kind</th><th class=\"n\">violations</th><th class=\"n\">listed</th></tr></thead><tbody>\n";
  for (std::size_t r = 0; r < report.count_by_reason.size(); ++r) {
    if (report.count_by_reason[r] == 0) continue;
    const auto reason = static_cast<Reason>(r);
    out += fmt::format("<tr data-reason=\"{0}\" data-count=\"{1}\"><td>{2}</td><td><a href=\"#kind-{0}\">{0}</a></td><td class=\"n\">{1}</td><td class=\"n\">{3}</td></tr>\n",
                       to_string(reason), report.count_by_reason[r], to_string(check_of(reason)), listed[reason]);
  }
  out += "</tbody></table>\n";
  return out;
}

std::string statistics_table(const Report& report) {
  const Statistics& s = report.stats;
  std::string out = "<table id=\"statistics\"><tbody>\n";
  out += row({"vertices", std::to_string(s.vertices)});
  out += row({"triangles", std::to_string(s.triangles)});
  out += row({"edges", std::to_string(s.edges)});
  out += row({"smallest angle", fmt::format("{:.4f}°", s.min_angle_deg)});
  out += row({"average smallest angle", fmt::format("{:.4f}°", s.avg_min_angle_deg)});
  out += row({"smallest area quality q", fmt::format("{:.4f}", s.min_area_quality)});
  out += row({"shortest edge", fmt::format("{:.6g} ({:.6g} × shortest input segment)", s.shortest_edge, s.shortest_edge_ratio)});
  out += row({"average Lepp size", fmt::format("{:.4f}", s.avg_lepp_size)});
  out += row({"Euler characteristic", fmt::format("{} (domain {})", s.euler_mesh, s.euler_domain)});
  out += row({"in-circle tests (cocircular)", fmt::format("{} ({})", s.delaunay_edges_checked, s.cocircular_edges)});
  out += row({"constrained edges", std::to_string(s.constrained_edges)});
  out += row({"terminal pairs checked (Theorem 2)", std::to_string(s.terminal_pairs_checked)});
  out += row({"theta checked", report.min_angle_deg > 0 ? fmt::format("{:g}°", report.min_angle_deg) : std::string("none")});
  if (!report.unimprovable_accepted.empty())
    out += row({"below theta, accepted as unimprovable", std::to_string(report.unimprovable_accepted.size())});
  if (report.exempt_count > 0) out += row({"below theta, exempt (small input angle)", std::to_string(report.exempt_count)});
  if (report.precision_exempt_count > 0)
    out += row({"below theta, exempt (precision limit)", std::to_string(report.precision_exempt_count)});
  if (report.max_area > 0 || report.region_area_bounds) out += row({"triangles checked against a size bound", std::to_string(report.area_checked)});
  out += "</tbody></table>\n";
  for (const std::string& w : report.warnings) out += "<p class=\"warning\">warning: " + escape(w) + "</p>\n";
  return out;
}

std::string histogram(html::Page& page, const Mesh& mesh, const Report& report) {
  std::vector<double> angles;
  angles.reserve(mesh.triangles.size());
  for (const Tri& t : mesh.triangles) {
    if (!valid_vertex(mesh, t[0]) || !valid_vertex(mesh, t[1]) || !valid_vertex(mesh, t[2])) continue;
    angles.push_back(min_angle_deg(mesh.vertices[static_cast<std::size_t>(t[0])], mesh.vertices[static_cast<std::size_t>(t[1])],
                                   mesh.vertices[static_cast<std::size_t>(t[2])]));
  }
  html::HistogramOptions o;
  o.x_label = "smallest angle of a triangle (degrees)";
  if (report.min_angle_deg > 0) o.mark = report.min_angle_deg, o.mark_label = fmt::format("theta {:g}°", report.min_angle_deg);
  const std::size_t below = report.min_angle_deg > 0 ? static_cast<std::size_t>(std::count_if(angles.begin(), angles.end(), [&](double a) {
                                                        return a < report.min_angle_deg;
                                                      }))
                                                    : 0;
  return page.figure(html::histogram_svg(angles, o),
                     fmt::format("{} triangles by smallest angle, one bar per degree{}", angles.size(),
                                 report.min_angle_deg > 0 ? fmt::format("; {} below theta (red; exempt ones included)", below) : ""),
                     "histogram");
}

std::string no_picture(const std::string& why) { return "<p class=\"bad no-picture\">no picture: " + escape(why) + "</p>\n"; }

std::string violation_block(html::Page& page, const Mesh& mesh, const Report& report, const Violation& v) {
  std::string out = fmt::format("<div class=\"violation\" data-reason=\"{}\">", to_string(v.reason));
  try {
    if (const auto svg = detail::violation_zoom_svg(mesh, report, v)) out += page.figure(*svg, "", "zoom");
  } catch (const std::exception& e) {
    out += no_picture(e.what());
  }
  out += "<div class=\"words\"><p>" + escape(v.message) + "</p>";
  const std::string xy = coordinates(mesh, v);
  if (!xy.empty()) out += "<pre class=\"coords\">" + escape(xy) + "</pre>";
  return out + "</div></div>\n";
}

std::string violations(html::Page& page, const Mesh& mesh, const Report& report, std::size_t shown) {
  std::map<Reason, std::vector<const Violation*>> by_reason;
  for (const Violation& v : report.violations) by_reason[v.reason].push_back(&v);
  std::string out;
  for (std::size_t r = 0; r < report.count_by_reason.size(); ++r) {
    const std::size_t count = report.count_by_reason[r];
    if (count == 0) continue;
    const auto reason = static_cast<Reason>(r);
    const std::vector<const Violation*>& listed = by_reason[reason];
    out += fmt::format("<section class=\"kind\" id=\"kind-{0}\" data-reason=\"{0}\" data-count=\"{1}\" data-listed=\"{2}\">\n<h3>{0} ({3}): {1}</h3>\n<p>{4}</p>\n",
                       to_string(reason), count, listed.size(), to_string(check_of(reason)), escape(explanation(reason)));
    for (std::size_t i = 0; i < std::min(shown, listed.size()); ++i) out += violation_block(page, mesh, report, *listed[i]);
    if (listed.size() > shown) {
      std::string rest;
      for (std::size_t i = shown; i < listed.size(); ++i) rest += violation_block(page, mesh, report, *listed[i]);
      out += html::details(fmt::format("show all {} listed ({} more)", listed.size(), listed.size() - shown), rest);
    }
    if (count > listed.size())
      out += fmt::format("<p>{} more counted, not listed (lepp certify --max-listed).</p>\n", count - listed.size());
    out += "</section>\n";
  }
  return out;
}

}  // namespace

std::string html_report(const Mesh& mesh, const Report& report, const HtmlOptions& options) {
  html::Page page("lepp certify: " + options.title);
  page.add("<h1>Certificate: " + escape(options.title) + "</h1>\n");
  if (!options.command.empty()) page.add("<p><code>" + escape(options.command) + "</code></p>\n");
  page.add(verdict(report));
  if (!report.certified()) page.add("<h2>Violations by kind</h2>\n" + counts_table(report));
  page.add("<h2>Statistics</h2>\n" + statistics_table(report));
  page.add("<h2>Smallest angles</h2>\n" + histogram(page, mesh, report));
  std::string overview;
  try {
    overview = page.figure(detail::overview_svg(mesh, report, options.outline_above),
                           mesh.triangles.size() > options.outline_above
                               ? fmt::format("{} triangles: the outline only (boundary, constrained edges, violations marked)", mesh.triangles.size())
                               : "The mesh, triangles coloured by smallest angle, listed violations in red",
                           "overview");
  } catch (const std::exception& e) {
    overview = no_picture(e.what());
  }
  page.add("<h2>The mesh</h2>\n" + overview);
  if (!report.certified()) page.add("<h2>Each violation</h2>\n" + violations(page, mesh, report, options.shown_per_reason));
  return page.str();
}

}  // namespace lepp::certify
