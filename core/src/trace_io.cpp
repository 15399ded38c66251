// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind lepp/trace_io.h: PREFIX.trace, the trace of every insertion, read and written.
#include "lepp/trace_io.h"

#include <fmt/format.h>

#include "block_file.h"
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
  // Through BlockFile, whose writes and close are checked (std::system_error naming
  // the file): a full disk shows only when the buffer is written, often at the close.
  detail::BlockFile out(path);
  out.print("# {} Steiner points in insertion order: x y\n", points.size());
  for (const Point& p : points) out.print("{:.17g} {:.17g}\n", p.x, p.y);  // as printf's %.17g
  out.close();
}

std::vector<Point> trace_points(const std::vector<TraceStep>& steps) {
  std::vector<Point> points;
  points.reserve(steps.size());
  for (const TraceStep& step : steps) points.push_back(step.point);
  return points;
}

}  // namespace lepp
