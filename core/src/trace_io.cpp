// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind lepp/trace_io.h: PREFIX.trace, the trace of every insertion, read and written.
#include "lepp/trace_io.h"

#include <cstdio>
#include <memory>
#include <stdexcept>

#include "lepp/io.h"
#include "line_reader.h"

namespace lepp {

std::vector<Point> read_trace(const std::string& path) {
  detail::LineReader in(path);
  std::vector<Point> points;
  std::vector<std::string_view> tokens;
  while (in.next(tokens)) {
    if (tokens.size() < 2) in.fail("expected a point 'x y'");
    points.push_back({in.real(tokens[0], "x"), in.real(tokens[1], "y")});
  }
  return points;
}

void write_trace(const std::string& path, const std::vector<Point>& points) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "w"), &std::fclose);
  if (!f) throw std::runtime_error("cannot write " + path);
  std::fprintf(f.get(), "# %zu Steiner points in insertion order: x y\n", points.size());
  for (const Point& p : points) std::fprintf(f.get(), "%.17g %.17g\n", p.x, p.y);
  if (std::ferror(f.get())) throw std::runtime_error("cannot write " + path);
}

std::vector<Point> trace_points(const std::vector<TraceStep>& steps) {
  std::vector<Point> points;
  points.reserve(steps.size());
  for (const TraceStep& step : steps) points.push_back(step.point);
  return points;
}

}  // namespace lepp
