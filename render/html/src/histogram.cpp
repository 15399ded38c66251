// SPDX-License-Identifier: GPL-3.0-or-later
// A histogram drawn as SVG (lepp/html/histogram.h).
#include "lepp/html/histogram.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "lepp/html/page.h"

namespace lepp::html {

std::string histogram_svg(const std::vector<double>& values, const HistogramOptions& o) {
  const std::size_t bins = std::max<std::size_t>(o.bins, 1);
  const double span = o.hi > o.lo ? o.hi - o.lo : 1;
  std::vector<std::size_t> count(bins, 0);
  for (double v : values) {
    if (!std::isfinite(v)) continue;
    const double at = std::floor((v - o.lo) / span * static_cast<double>(bins));
    ++count[static_cast<std::size_t>(std::clamp(at, 0.0, static_cast<double>(bins - 1)))];
  }
  const std::size_t top = std::max<std::size_t>(*std::max_element(count.begin(), count.end()), 1);
  const double left = 56, right = 12, top_pad = 14, bottom = 42;
  const double plot_w = o.width - left - right, plot_h = o.height - top_pad - bottom;
  const double bar_w = plot_w / static_cast<double>(bins);
  auto x_of = [&](double v) { return left + (v - o.lo) / span * plot_w; };
  std::string s = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" viewBox=\"0 0 {:.0f} {:.0f}\" "
      "font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      o.width, o.height, o.width, o.height);
  for (std::size_t i = 0; i < bins; ++i) {
    if (count[i] == 0) continue;
    const double h = std::max(1.0, plot_h * static_cast<double>(count[i]) / static_cast<double>(top));
    const double bin_hi = o.lo + span * static_cast<double>(i + 1) / static_cast<double>(bins);
    const bool below = o.mark >= o.lo && bin_hi <= o.mark;
    s += fmt::format("<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"{}\"><title>{}</title></rect>\n",
                     left + bar_w * static_cast<double>(i), top_pad + plot_h - h, std::max(bar_w - 1, 0.5), h,
                     below ? "#c0392b" : "#3e6fb0", count[i]);
  }
  // Axes, five ticks on each.
  s += fmt::format("<path fill=\"none\" stroke=\"#333\" d=\"M{0:.1f} {1:.1f}V{2:.1f}H{3:.1f}\"/>\n", left, top_pad,
                   top_pad + plot_h, left + plot_w);
  for (int k = 0; k <= 4; ++k) {
    const double v = o.lo + span * k / 4, x = x_of(v);
    s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{:g}</text>\n", x, top_pad + plot_h + 14, v);
    const double c = static_cast<double>(top) * k / 4, y = top_pad + plot_h - plot_h * k / 4;
    s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"end\">{:.0f}</text>\n", left - 4, y + 4, c);
  }
  s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{}</text>\n", left + plot_w / 2, o.height - 6,
                   escape(o.x_label));
  if (o.mark >= o.lo && o.mark <= o.hi) {
    const double x = x_of(o.mark);
    s += fmt::format("<path stroke=\"#b00020\" stroke-width=\"1.5\" stroke-dasharray=\"4 3\" d=\"M{0:.1f} {1:.1f}V{2:.1f}\"/>\n", x,
                     top_pad, top_pad + plot_h);
    s += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" fill=\"#b00020\">{}</text>\n", x + 4, top_pad + 10, escape(o.mark_label));
  }
  s += "</svg>\n";
  return s;
}

}  // namespace lepp::html
