// SPDX-License-Identifier: GPL-3.0-or-later
// The input: a planar straight line graph, as read from a Triangle .poly file.
#pragma once
#include <string>
#include <vector>

namespace lepp {

struct Point {
  double x = 0, y = 0;
  friend bool operator==(const Point& a, const Point& b) { return a.x == b.x && a.y == b.y; }
  friend bool operator!=(const Point& a, const Point& b) { return !(a == b); }
};

// An input segment between vertices a and b (0-based ids into Pslg::vertices).
struct Segment {
  int a = 0, b = 0;
  int marker = 0;  // Triangle's boundary marker, kept, never interpreted
};

struct Pslg {
  std::vector<Point> vertices;
  std::vector<int> vertex_markers;  // empty, or one per vertex
  std::vector<Segment> segments;
  std::vector<Point> holes;

  // Where each item was read (file name and 1-based line), so that errors found
  // after parsing (crossing segments, ...) can still name the line. Empty for
  // PSLGs that were generated rather than read.
  std::string source;
  std::vector<int> vertex_lines, segment_lines, hole_lines;
};

}  // namespace lepp
