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

// A regional attribute / area constraint of Triangle's .poly (its section after
// the holes): the region of the domain around `at`, bounded by segments.
struct Region {
  Point at;
  double attribute = 0;
  double max_area = -1;  // <= 0: no area bound (Triangle's convention)
};

struct Pslg {
  std::vector<Point> vertices;
  std::vector<int> vertex_markers;  // empty, or one per vertex
  std::vector<Segment> segments;
  std::vector<Point> holes;
  std::vector<Region> regions;  // read from the .poly; the engines do not use them (docs/FORMATS.md)

  // Where each item was read (file name and 1-based line), so that errors found
  // after parsing (crossing segments, ...) can still name the line. Empty for
  // PSLGs that were generated rather than read.
  std::string source;
  std::vector<int> vertex_lines, segment_lines, hole_lines, region_lines;

  // After validate(): for each segment (a piece), the 0-based number of the
  // file's segment it is part of (pieces of one segment are consecutive, from
  // its first endpoint to its second). Empty before validation.
  std::vector<int> segment_origin;
  // After validate() with --split-crossings: the last `crossing_vertices`
  // vertices are crossing points, the exact intersections rounded to doubles
  // (another mesher may have rounded them otherwise: the certifier allows it).
  std::size_t crossing_vertices = 0;
};

}  // namespace lepp
