// SPDX-License-Identifier: GPL-3.0-or-later
// `lepp render MESH_PREFIX -o out.svg`: draws a mesh as SVG, triangles coloured
// by quality or smallest angle, constrained edges bold, bad triangles marked.
// Compact at 10^5 triangles (about 25 bytes each): one <path> per colour bin,
// coordinates rounded to a tenth of a pixel, relative moves.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.h"
#include "lepp/io.h"
#include "lepp/stats.h"

namespace lepp::cli {
namespace {

struct RenderArgs {
  std::string prefix, output;
  std::string color = "quality";
  std::string highlight = "none";
  double min_angle = 30;
  double width = 1000;
  std::string title;
};

// Viridis, ten samples: dark is poor, yellow is good.
constexpr std::array<const char*, 10> kPalette = {"#440154", "#482878", "#3e4989", "#31688e", "#26828e",
                                                  "#1f9e89", "#35b779", "#6ece58", "#b5de2b", "#fde725"};

// Maps mesh coordinates to SVG pixels (y up in the mesh, down in SVG).
struct Viewport {
  double min_x = 0, max_y = 0, scale = 1, margin = 10;
  double x(double mx) const { return margin + (mx - min_x) * scale; }
  double y(double my) const { return margin + (max_y - my) * scale; }
};

// A tenth of a pixel: enough for 10^5 triangles on a 1000-pixel canvas.
long tenth(double v) { return std::lround(v * 10); }
std::string num(long tenths) {
  if (tenths % 10 == 0) return std::to_string(tenths / 10);
  return fmt::format("{}{}.{}", tenths < 0 ? "-" : "", std::labs(tenths) / 10, std::labs(tenths) % 10);
}

// The path data of one colour: closed triangles "m dx dy l dx dy dx dy z", each
// move relative to where the previous triangle started (where "z" leaves the pen).
struct PathData {
  std::string d;
  long x = 0, y = 0;  // pen position, tenths of pixels

  void triangle(const Viewport& vp, const Point& a, const Point& b, const Point& c) {
    long ax = tenth(vp.x(a.x)), ay = tenth(vp.y(a.y));
    long bx = tenth(vp.x(b.x)), by = tenth(vp.y(b.y));
    long cx = tenth(vp.x(c.x)), cy = tenth(vp.y(c.y));
    d += (d.empty() ? "M" : "m") + num(ax - x) + " " + num(ay - y) + "l" + num(bx - ax) + " " + num(by - ay) + " " +
         num(cx - bx) + " " + num(cy - by) + "z";
    x = ax, y = ay;
  }
};

int run_render(const RenderArgs& args) {
  Mesh mesh;
  try {
    mesh = read_mesh(args.prefix);
  } catch (const InputError& e) {
    std::fprintf(stderr, "lepp render: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lepp render: %s\n", e.what());
    return 2;
  }
  if (mesh.triangles.empty()) {
    std::fprintf(stderr, "lepp render: %s has no triangles\n", args.prefix.c_str());
    return 2;
  }

  // Only vertices of triangles count for the bounding box (input vertices in holes do not).
  double min_x = INFINITY, min_y = INFINITY, max_x = -INFINITY, max_y = -INFINITY;
  for (const Tri& t : mesh.triangles)
    for (int v : t) {
      const Point& p = mesh.vertices[static_cast<std::size_t>(v)];
      min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
      min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
    }
  Viewport vp;
  double extent = std::max(max_x - min_x, max_y - min_y);
  vp.min_x = min_x;
  vp.max_y = max_y;
  vp.scale = extent > 0 ? (args.width - 2 * vp.margin) / extent : 1;
  double canvas_w = 2 * vp.margin + (max_x - min_x) * vp.scale;
  double canvas_h = 2 * vp.margin + (max_y - min_y) * vp.scale;
  double legend_h = 46;

  const bool by_angle = args.color == "angle";
  std::array<PathData, kPalette.size()> bins;
  PathData bad_outlines;
  std::string bad_marks;
  std::size_t bad = 0;
  double worst_angle = 90;
  const double mark_r = 3;
  for (const Tri& t : mesh.triangles) {
    const Point& a = mesh.vertices[static_cast<std::size_t>(t[0])];
    const Point& b = mesh.vertices[static_cast<std::size_t>(t[1])];
    const Point& c = mesh.vertices[static_cast<std::size_t>(t[2])];
    double angle = min_angle_deg(a, b, c);
    worst_angle = std::min(worst_angle, angle);
    double value = by_angle ? angle / 60.0 : area_quality(a, b, c);
    auto bin = static_cast<std::size_t>(std::clamp(value, 0.0, 0.999999) * kPalette.size());
    bins[bin].triangle(vp, a, b, c);
    if (angle < args.min_angle) {
      ++bad;
      if (args.highlight == "bad") {
        bad_outlines.triangle(vp, a, b, c);
        // A ring at the centroid, visible when the triangle itself is a hair.
        long gx = tenth(vp.x((a.x + b.x + c.x) / 3) - mark_r), gy = tenth(vp.y((a.y + b.y + c.y) / 3));
        bad_marks += "M" + num(gx) + " " + num(gy) + "a3 3 0 1 0 6 0a3 3 0 1 0 -6 0";
      }
    }
  }
  std::string constrained;
  for (const ConstrainedEdge& e : mesh.constrained_edges) {
    const Point& a = mesh.vertices[static_cast<std::size_t>(e.a)];
    const Point& b = mesh.vertices[static_cast<std::size_t>(e.b)];
    long ax = tenth(vp.x(a.x)), ay = tenth(vp.y(a.y)), bx = tenth(vp.x(b.x)), by = tenth(vp.y(b.y));
    constrained += "M" + num(ax) + " " + num(ay) + "l" + num(bx - ax) + " " + num(by - ay);
  }

  // Mesh lines thin out as triangles grow in number, so colour still shows.
  double edge_w = std::clamp(std::sqrt(canvas_w * canvas_h / static_cast<double>(mesh.triangles.size())) / 25, 0.05, 0.6);

  std::ofstream out(args.output);
  if (!out) {
    std::fprintf(stderr, "lepp render: cannot write %s\n", args.output.c_str());
    return 1;
  }
  out << fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" viewBox=\"0 0 {:.0f} {:.0f}\">\n",
      canvas_w, canvas_h + legend_h, canvas_w, canvas_h + legend_h);
  out << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  out << fmt::format("<g stroke=\"#222\" stroke-width=\"{:.2f}\" stroke-linejoin=\"round\">\n", edge_w);
  for (std::size_t i = 0; i < bins.size(); ++i)
    if (!bins[i].d.empty()) out << "<path fill=\"" << kPalette[i] << "\" d=\"" << bins[i].d << "\"/>\n";
  out << "</g>\n";
  out << "<path fill=\"none\" stroke=\"black\" stroke-width=\"2\" stroke-linecap=\"round\" d=\"" << constrained << "\"/>\n";
  if (!bad_outlines.d.empty()) {
    out << "<path fill=\"#ff000040\" stroke=\"red\" stroke-width=\"1.2\" d=\"" << bad_outlines.d << "\"/>\n";
    out << "<path fill=\"none\" stroke=\"red\" stroke-width=\"1\" d=\"" << bad_marks << "\"/>\n";
  }

  // Legend: the colour scale and a one-line summary.
  double ly = canvas_h + 6, sw = std::min(30.0, (canvas_w - 20) / 20);
  out << "<g font-family=\"sans-serif\" font-size=\"11\">\n";
  for (std::size_t i = 0; i < kPalette.size(); ++i) {
    out << fmt::format("<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"10\" fill=\"{}\"/>\n",
                       vp.margin + static_cast<double>(i) * sw, ly, sw, kPalette[i]);
  }
  for (std::size_t i = 0; i <= kPalette.size(); i += 5) {
    double v = static_cast<double>(i) / kPalette.size() * (by_angle ? 60.0 : 1.0);
    out << fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\">{}</text>\n", vp.margin + static_cast<double>(i) * sw - 3,
                       ly + 22, by_angle ? fmt::format("{:.0f}°", v) : fmt::format("{:.1f}", v));
  }
  std::string summary = fmt::format("{}{} vertices, {} triangles, smallest angle {:.2f}°, {} below {:g}°",
                                    args.title.empty() ? "" : args.title + ": ", mesh.vertices.size(),
                                    mesh.triangles.size(), worst_angle, bad, args.min_angle);
  out << fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\">colour: {}; {}</text>\n", vp.margin, ly + 36,
                     by_angle ? "smallest angle" : "area quality q", summary);
  out << "</g>\n</svg>\n";
  if (!out) {
    std::fprintf(stderr, "lepp render: cannot write %s\n", args.output.c_str());
    return 1;
  }
  return 0;
}

}  // namespace

void add_render_command(CLI::App& app, int& status) {
  auto args = std::make_shared<RenderArgs>();
  auto* cmd = app.add_subcommand("render", "Draw a mesh (PREFIX.node/.ele/.poly) as SVG, coloured by quality");
  cmd->add_option("prefix", args->prefix, "Mesh prefix: reads PREFIX.node, PREFIX.ele and PREFIX.poly if present")
      ->required();
  cmd->add_option("-o,--output", args->output, "SVG file to write")->required();
  cmd->add_option("--color", args->color, "Colour triangles by area quality q (1 = equilateral) or smallest angle")
      ->default_val("quality")
      ->check(CLI::IsMember({"quality", "angle"}));
  cmd->add_option("--highlight", args->highlight, "bad: outline and ring the triangles with smallest angle below --min-angle")
      ->default_val("none")
      ->check(CLI::IsMember({"none", "bad"}));
  cmd->add_option("--min-angle", args->min_angle, "Angle below which a triangle is bad, degrees")
      ->default_val(30)
      ->check(CLI::Range(0.0, 60.0));
  cmd->add_option("--width", args->width, "Drawing width in pixels")->default_val(1000)->check(CLI::Range(100.0, 20000.0));
  cmd->add_option("--title", args->title, "Text put before the summary line under the drawing");
  cmd->footer("Exit status: 0 written; 2 the mesh cannot be read; 1 the SVG cannot be written.");
  cmd->callback([args, &status] { status = run_render(*args); });
}

}  // namespace lepp::cli
