// SPDX-License-Identifier: GPL-3.0-or-later
// lepp::render::render_svg: highlights and windows draw what they are given and
// nothing else; bad ids are refused. (`lepp render`'s own bytes are checked by the
// paper/ tests, check_svg.py.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "lepp/io.h"
#include "lepp/render.h"

namespace lepp {
namespace {

Mesh sample() { return read_mesh(LEPP_SOURCE_DIR "/paper/testdata/A-triangle-q30"); }

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + what.size())) ++n;
  return n;
}

// The d attribute of the first <path> whose opening text contains `marker`.
std::string path_with(const std::string& svg, const std::string& marker) {
  const std::size_t at = svg.find(marker);
  if (at == std::string::npos) return {};
  const std::size_t d = svg.find(" d=\"", at);
  return svg.substr(d + 4, svg.find('"', d + 4) - d - 4);
}

TEST(RenderSvg, WholeMeshHasEveryTriangleOnceAndNoWindow) {
  const Mesh m = sample();
  const std::string svg = render::render_svg(m);
  ASSERT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
  // Every triangle is one closed sub-path ("z") in the colour bins; constrained edges draw none.
  std::size_t closed = 0;
  for (const char* colour : {"#440154", "#482878", "#3e4989", "#31688e", "#26828e", "#1f9e89", "#35b779", "#6ece58", "#b5de2b", "#fde725"})
    closed += count(path_with(svg, std::string("<path fill=\"") + colour + "\""), "z");
  EXPECT_EQ(closed, m.triangles.size());
  EXPECT_EQ(count(svg, "clipPath"), 0u);
  EXPECT_NE(svg.find(std::to_string(m.triangles.size()) + " triangles"), std::string::npos);
}

TEST(RenderSvg, HighlightsDrawTheGivenTrianglesEdgesAndPoints) {
  const Mesh m = sample();
  render::RenderOptions o;
  render::Highlight h;
  h.triangles = {0, 3};
  h.edges = {{m.triangles[5][0], m.triangles[5][1]}};
  h.points = {{0.5, 0.5}, {1, 1}, {2, 2}};
  h.colour = "#00aaff";
  h.label = "violation <here>";
  o.highlights.push_back(h);
  const std::string svg = render::render_svg(m, o);
  EXPECT_EQ(count(path_with(svg, "fill=\"#00aaff\" fill-opacity"), "z"), 2u);             // two triangles outlined
  EXPECT_EQ(count(path_with(svg, "stroke=\"#00aaff\" stroke-width=\"3.5\""), "M"), 1u);  // one edge
  EXPECT_EQ(count(path_with(svg, "stroke=\"#00aaff\" stroke-width=\"2\""), "M"), 3u);    // three point rings
  EXPECT_NE(svg.find("violation &lt;here>"), std::string::npos);                          // the label, escaped
  // Without highlights none of it.
  EXPECT_EQ(render::render_svg(m).find("#00aaff"), std::string::npos);
}

TEST(RenderSvg, WindowDrawsOnlyTheTrianglesMeetingIt) {
  const Mesh m = sample();
  render::RenderOptions o;
  o.window = render::window_around(m, {7}, {}, 0.5);
  const render::Window& w = *o.window;
  std::size_t meeting = 0;
  for (const Tri& t : m.triangles) {
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (int v : t) {
      const Point& p = m.vertices[static_cast<std::size_t>(v)];
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
    meeting += x1 >= w.min_x && x0 <= w.max_x && y1 >= w.min_y && y0 <= w.max_y;
  }
  ASSERT_LT(meeting, m.triangles.size());  // a real crop
  ASSERT_GE(meeting, 1u);
  const std::string svg = render::render_svg(m, o);
  EXPECT_NE(svg.find(": " + std::to_string(meeting) + " triangles drawn"), std::string::npos);
  EXPECT_EQ(count(svg, "clip-path=\"url(#window)\""), 1u);
  // The window holds triangle 7 and is square.
  for (int v : m.triangles[7]) {
    const Point& p = m.vertices[static_cast<std::size_t>(v)];
    EXPECT_TRUE(p.x > w.min_x && p.x < w.max_x && p.y > w.min_y && p.y < w.max_y);
  }
  EXPECT_NEAR(w.max_x - w.min_x, w.max_y - w.min_y, 1e-12 * (w.max_x - w.min_x));
}

TEST(RenderSvg, RefusesBadIdsAndEmptyMeshes) {
  const Mesh m = sample();
  render::RenderOptions o;
  o.highlights.push_back({{static_cast<int>(m.triangles.size())}, {}, {}, "red", ""});
  EXPECT_THROW(render::render_svg(m, o), std::invalid_argument);
  o.highlights = {{{}, {{0, static_cast<int>(m.vertices.size())}}, {}, "red", ""}};
  EXPECT_THROW(render::render_svg(m, o), std::invalid_argument);
  EXPECT_THROW(render::render_svg(Mesh{}), std::invalid_argument);
  EXPECT_THROW(render::window_around(m, {}, {}), std::invalid_argument);
}

}  // namespace
}  // namespace lepp
