// SPDX-License-Identifier: GPL-3.0-or-later
// A histogram as an SVG document: the triangles' smallest angles against theta on
// a certificate's page (and any other distribution a report shows).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace lepp::html {

struct HistogramOptions {
  double lo = 0, hi = 60;     // the axis; values outside are counted in the end bins
  std::size_t bins = 60;
  double mark = -1;           // a vertical line here (theta) when lo <= mark <= hi
  std::string mark_label;     // "theta 30°"
  std::string x_label;        // "smallest angle (degrees)"
  double width = 640, height = 220;
};

// Bars of the counts (the bins left of `mark` red, the others blue), the axis with
// ticks, the mark and the labels. Values that are not finite are left out.
std::string histogram_svg(const std::vector<double>& values, const HistogramOptions& options);

}  // namespace lepp::html
