// SPDX-License-Identifier: GPL-3.0-or-later
// The SVG drawing of a mesh. Compact at 10^5 triangles (about 25 bytes each): one
// <path> per colour bin, coordinates rounded to a tenth of a pixel, relative moves.
#include "lepp/render.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include <fmt/format.h>

#include "lepp/stats.h"

namespace lepp::render {
namespace {

// Viridis, ten samples: dark is poor, yellow is good.
constexpr std::array<const char*, 10> kPalette = {"#440154", "#482878", "#3e4989", "#31688e", "#26828e",
                                                  "#1f9e89", "#35b779", "#6ece58", "#b5de2b", "#fde725"};

// Maps mesh coordinates to SVG pixels (y up in the mesh, down in SVG).
struct Viewport {
  double min_x = 0, max_y = 0, scale = 1, margin = 10;
  double x(double mx) const { return margin + (mx - min_x) * scale; }
  double y(double my) const { return margin + (max_y - my) * scale; }
};

// A tenth of a pixel: enough for 10^5 triangles on a 1000-pixel canvas. Clamped so
// that a vertex far outside a small window cannot overflow (inside the canvas, no effect).
long tenth(double v) { return std::lround(std::clamp(v * 10, -1e15, 1e15)); }
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

std::string segment_path(const Viewport& vp, const Point& a, const Point& b) {
  long ax = tenth(vp.x(a.x)), ay = tenth(vp.y(a.y)), bx = tenth(vp.x(b.x)), by = tenth(vp.y(b.y));
  return "M" + num(ax) + " " + num(ay) + "l" + num(bx - ax) + " " + num(by - ay);
}

// A ring of radius r pixels around (px, py) pixels.
std::string ring(double px, double py, double r) {
  long gx = tenth(px - r), gy = tenth(py);
  const std::string rs = num(tenth(r)), ds = num(tenth(2 * r));
  return "M" + num(gx) + " " + num(gy) + "a" + rs + " " + rs + " 0 1 0 " + ds + " 0a" + rs + " " + rs + " 0 1 0 -" + ds + " 0";
}

const Point& vertex(const Mesh& mesh, int id) {
  if (id < 0 || static_cast<std::size_t>(id) >= mesh.vertices.size())
    throw std::invalid_argument(fmt::format("render: vertex id {} out of range", id));
  return mesh.vertices[static_cast<std::size_t>(id)];
}

const Tri& triangle(const Mesh& mesh, int t) {
  if (t < 0 || static_cast<std::size_t>(t) >= mesh.triangles.size())
    throw std::invalid_argument(fmt::format("render: triangle {} out of range", t));
  return mesh.triangles[static_cast<std::size_t>(t)];
}

bool meets(const Window& w, const Point& a, const Point& b, const Point& c) {
  return std::max({a.x, b.x, c.x}) >= w.min_x && std::min({a.x, b.x, c.x}) <= w.max_x && std::max({a.y, b.y, c.y}) >= w.min_y &&
         std::min({a.y, b.y, c.y}) <= w.max_y;
}

// The edges of exactly one triangle (the mesh's boundary, holes included), as vertex id pairs.
// Sorted 64-bit keys, not a hash map: 3 x 10^6 edges in a fraction of a second.
std::vector<std::array<int, 2>> boundary_edges(const Mesh& mesh) {
  std::vector<std::uint64_t> keys;
  keys.reserve(3 * mesh.triangles.size());
  for (const Tri& t : mesh.triangles)
    for (std::size_t i = 0; i < 3; ++i) {
      const auto a = static_cast<std::uint32_t>(std::min(t[i], t[(i + 1) % 3]));
      const auto b = static_cast<std::uint32_t>(std::max(t[i], t[(i + 1) % 3]));
      keys.push_back(std::uint64_t{a} << 32 | b);
    }
  std::sort(keys.begin(), keys.end());
  std::vector<std::array<int, 2>> out;
  for (std::size_t i = 0; i < keys.size();) {
    std::size_t j = i;
    while (j < keys.size() && keys[j] == keys[i]) ++j;
    if (j - i == 1) out.push_back({static_cast<int>(keys[i] >> 32), static_cast<int>(keys[i] & 0xffffffffu)});
    i = j;
  }
  return out;
}

}  // namespace

Window window_around(const Mesh& mesh, const std::vector<int>& triangles, const std::vector<Point>& points, double context) {
  if (triangles.empty() && points.empty()) throw std::invalid_argument("render: a window around nothing");
  double min_x = INFINITY, min_y = INFINITY, max_x = -INFINITY, max_y = -INFINITY, longest = 0;
  auto add = [&](const Point& p) {
    min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
    min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
  };
  for (int t : triangles) {
    const Tri& x = triangle(mesh, t);
    for (std::size_t i = 0; i < 3; ++i) {
      const Point &a = vertex(mesh, x[i]), &b = vertex(mesh, x[(i + 1) % 3]);
      add(a);
      longest = std::max(longest, std::hypot(b.x - a.x, b.y - a.y));
    }
  }
  for (const Point& p : points) add(p);
  double side = std::max({max_x - min_x, max_y - min_y, longest});
  if (side <= 0) side = std::max({std::abs(min_x), std::abs(min_y), 1e-300}) * 1e-6;  // one point alone
  const double grow = std::max(context, 0.0) * side;
  // Square it, so the drawing is not stretched into a strip by a needle.
  const double cx = (min_x + max_x) / 2, cy = (min_y + max_y) / 2, half = side / 2 + grow;
  return {cx - half, cy - half, cx + half, cy + half};
}

std::string render_svg(const Mesh& mesh, const RenderOptions& options) {
  if (mesh.triangles.empty()) throw std::invalid_argument("render: the mesh has no triangles");
  for (const Highlight& h : options.highlights) {
    for (int t : h.triangles) triangle(mesh, t);
    for (const auto& e : h.edges) vertex(mesh, e[0]), vertex(mesh, e[1]);
  }
  for (const Tri& t : mesh.triangles)
    for (int v : t) vertex(mesh, v);

  // Only vertices of triangles count for the bounding box (input vertices in holes do not).
  double min_x = INFINITY, min_y = INFINITY, max_x = -INFINITY, max_y = -INFINITY;
  if (options.window) {
    min_x = options.window->min_x, max_x = options.window->max_x;
    min_y = options.window->min_y, max_y = options.window->max_y;
  } else {
    for (const Tri& t : mesh.triangles)
      for (int v : t) {
        const Point& p = mesh.vertices[static_cast<std::size_t>(v)];
        min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
        min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
      }
  }
  Viewport vp;
  double extent = std::max(max_x - min_x, max_y - min_y);
  vp.min_x = min_x;
  vp.max_y = max_y;
  vp.scale = extent > 0 ? (options.width - 2 * vp.margin) / extent : 1;
  double canvas_w = 2 * vp.margin + (max_x - min_x) * vp.scale;
  double canvas_h = 2 * vp.margin + (max_y - min_y) * vp.scale;
  std::size_t labels = 0;
  for (const Highlight& h : options.highlights) labels += !h.label.empty();
  double legend_h = 46 + 14 * static_cast<double>(labels) + (options.window ? 14 : 0);

  const bool by_angle = options.color == ColorBy::Angle;
  std::array<PathData, kPalette.size()> bins;
  PathData bad_outlines;
  std::string bad_marks;
  std::size_t bad = 0, drawn = 0;
  double worst_angle = 90;
  const double mark_r = 3;
  for (const Tri& t : mesh.triangles) {
    const Point& a = mesh.vertices[static_cast<std::size_t>(t[0])];
    const Point& b = mesh.vertices[static_cast<std::size_t>(t[1])];
    const Point& c = mesh.vertices[static_cast<std::size_t>(t[2])];
    double angle = min_angle_deg(a, b, c);
    worst_angle = std::min(worst_angle, angle);
    if (angle < options.min_angle_deg) ++bad;  // the summary counts the whole mesh, drawn or not
    if (options.window && !meets(*options.window, a, b, c)) continue;
    if (options.outline_only) continue;
    ++drawn;
    double value = by_angle ? angle / 60.0 : area_quality(a, b, c);
    auto bin = static_cast<std::size_t>(std::clamp(value, 0.0, 0.999999) * kPalette.size());
    bins[bin].triangle(vp, a, b, c);
    if (angle < options.min_angle_deg && options.highlight_bad) {
      bad_outlines.triangle(vp, a, b, c);
      // A ring at the centroid, visible when the triangle itself is a hair.
      long gx = tenth(vp.x((a.x + b.x + c.x) / 3) - mark_r), gy = tenth(vp.y((a.y + b.y + c.y) / 3));
      bad_marks += "M" + num(gx) + " " + num(gy) + "a3 3 0 1 0 6 0a3 3 0 1 0 -6 0";
    }
  }
  std::string constrained;
  for (const ConstrainedEdge& e : mesh.constrained_edges) {
    const Point& a = vertex(mesh, e.a);
    const Point& b = vertex(mesh, e.b);
    if (options.window && !meets(*options.window, a, b, b)) continue;
    constrained += segment_path(vp, a, b);
  }
  std::string boundary;
  if (options.outline_only)
    for (const auto& e : boundary_edges(mesh)) {
      const Point& a = mesh.vertices[static_cast<std::size_t>(e[0])];
      const Point& b = mesh.vertices[static_cast<std::size_t>(e[1])];
      if (options.window && !meets(*options.window, a, b, b)) continue;
      boundary += segment_path(vp, a, b);
    }

  // Mesh lines thin out as triangles grow in number, so colour still shows.
  double edge_w = std::clamp(std::sqrt(canvas_w * canvas_h / static_cast<double>(std::max<std::size_t>(drawn, 1))) / 25, 0.05, 0.6);

  std::string out;
  out += fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" viewBox=\"0 0 {:.0f} {:.0f}\">\n",
      canvas_w, canvas_h + legend_h, canvas_w, canvas_h + legend_h);
  out += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  if (options.window) {
    // Everything of the mesh is clipped to the window's rectangle.
    out += fmt::format("<defs><clipPath id=\"window\"><rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\"/></clipPath></defs>\n",
                       vp.margin, vp.margin, canvas_w - 2 * vp.margin, canvas_h - 2 * vp.margin);
    out += "<g clip-path=\"url(#window)\">\n";
  }
  out += fmt::format("<g stroke=\"#222\" stroke-width=\"{:.2f}\" stroke-linejoin=\"round\">\n", edge_w);
  for (std::size_t i = 0; i < bins.size(); ++i)
    if (!bins[i].d.empty()) out += std::string("<path fill=\"") + kPalette[i] + "\" d=\"" + bins[i].d + "\"/>\n";
  out += "</g>\n";
  if (!boundary.empty())
    out += "<path fill=\"none\" stroke=\"#555\" stroke-width=\"1.2\" stroke-linecap=\"round\" d=\"" + boundary + "\"/>\n";
  out += "<path fill=\"none\" stroke=\"black\" stroke-width=\"2\" stroke-linecap=\"round\" d=\"" + constrained + "\"/>\n";
  if (!bad_outlines.d.empty()) {
    out += "<path fill=\"#ff000040\" stroke=\"red\" stroke-width=\"1.2\" d=\"" + bad_outlines.d + "\"/>\n";
    out += "<path fill=\"none\" stroke=\"red\" stroke-width=\"1\" d=\"" + bad_marks + "\"/>\n";
  }
  for (const Highlight& h : options.highlights) {
    PathData outlines;
    std::string marks, edges, points;
    for (int t : h.triangles) {
      const Tri& x = mesh.triangles[static_cast<std::size_t>(t)];
      const Point &a = mesh.vertices[static_cast<std::size_t>(x[0])], &b = mesh.vertices[static_cast<std::size_t>(x[1])],
                  &c = mesh.vertices[static_cast<std::size_t>(x[2])];
      outlines.triangle(vp, a, b, c);
      marks += ring(vp.x((a.x + b.x + c.x) / 3), vp.y((a.y + b.y + c.y) / 3), 4);
    }
    for (const auto& e : h.edges) edges += segment_path(vp, vertex(mesh, e[0]), vertex(mesh, e[1]));
    for (const Point& p : h.points) points += ring(vp.x(p.x), vp.y(p.y), 5);
    if (!outlines.d.empty()) {
      out += "<path fill=\"" + h.colour + "\" fill-opacity=\"0.25\" stroke=\"" + h.colour + "\" stroke-width=\"1.5\" d=\"" + outlines.d + "\"/>\n";
      out += "<path fill=\"none\" stroke=\"" + h.colour + "\" stroke-width=\"1\" d=\"" + marks + "\"/>\n";
    }
    if (!edges.empty())
      out += "<path fill=\"none\" stroke=\"" + h.colour + "\" stroke-width=\"3.5\" stroke-linecap=\"round\" d=\"" + edges + "\"/>\n";
    if (!points.empty()) out += "<path fill=\"none\" stroke=\"" + h.colour + "\" stroke-width=\"2\" d=\"" + points + "\"/>\n";
  }
  if (options.window) out += "</g>\n";

  // Legend: the colour scale and a one-line summary.
  double ly = canvas_h + 6, sw = std::min(30.0, (canvas_w - 20) / 20);
  out += "<g font-family=\"sans-serif\" font-size=\"11\">\n";
  for (std::size_t i = 0; i < kPalette.size(); ++i) {
    out += fmt::format("<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"10\" fill=\"{}\"/>\n",
                       vp.margin + static_cast<double>(i) * sw, ly, sw, kPalette[i]);
  }
  for (std::size_t i = 0; i <= kPalette.size(); i += 5) {
    double v = static_cast<double>(i) / kPalette.size() * (by_angle ? 60.0 : 1.0);
    out += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\">{}</text>\n", vp.margin + static_cast<double>(i) * sw - 3, ly + 22,
                       by_angle ? fmt::format("{:.0f}°", v) : fmt::format("{:.1f}", v));
  }
  std::string summary = fmt::format("{}{} vertices, {} triangles, smallest angle {:.2f}°, {} below {:g}°",
                                    options.title.empty() ? "" : options.title + ": ", mesh.vertices.size(), mesh.triangles.size(),
                                    worst_angle, bad, options.min_angle_deg);
  out += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\">colour: {}; {}</text>\n", vp.margin, ly + 36,
                     by_angle ? "smallest angle" : "area quality q", summary);
  double line = ly + 36;
  if (options.window) {
    line += 14;
    out += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\">window [{:g}, {:g}] x [{:g}, {:g}]: {} triangles drawn</text>\n", vp.margin,
                       line, options.window->min_x, options.window->max_x, options.window->min_y, options.window->max_y, drawn);
  }
  for (const Highlight& h : options.highlights) {
    if (h.label.empty()) continue;
    line += 14;
    std::string text;
    for (char ch : h.label) text += ch == '<' ? std::string("&lt;") : ch == '&' ? std::string("&amp;") : std::string(1, ch);
    out += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" fill=\"{}\">{}</text>\n", vp.margin, line, h.colour, text);
  }
  out += "</g>\n</svg>\n";
  return out;
}

}  // namespace lepp::render
