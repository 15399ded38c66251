// SPDX-License-Identifier: GPL-3.0-or-later
// Reading an input the way Triangle does (docs/FORMATS.md): a .poly or a .node
// alone, with the warnings Triangle's leniency calls for, and the domain
// options shared by `lepp refine` and `lepp certify` (convex hull, crossings).
#pragma once
#include <string>
#include <vector>

#include "lepp/pslg.h"

namespace lepp {

// As read_poly / read_node (lepp/io.h), collecting one warning per file for
// what Triangle tolerates: trailing fields beyond the header's (a column of
// them), optional fields left out.
Pslg read_poly(const std::string& path, std::vector<std::string>& warnings);
Pslg read_node(const std::string& path, std::vector<std::string>& warnings);
// A .node file is a point set; anything else is read as a .poly. A path that
// names no file (nothing there, or a directory) and ends in neither .poly nor
// .node is a prefix, as Triangle takes one: PATH.poly if it exists, else
// PATH.node (InputError naming the path and both files when neither does).
Pslg read_input(const std::string& path, std::vector<std::string>& warnings);

struct DomainOptions {
  bool convex_hull = false;      // Triangle's -c: add the convex hull's edges as segments
  bool split_crossings = false;  // split crossing segments at their (rounded) intersection
};

// The segments of the convex hull of the PSLG's vertices, every vertex on the
// hull's boundary included (collinear ones too), counter-clockwise, leaving
// out those the PSLG already has (either direction). Exact predicates.
// Markers are 1, Triangle's marker for boundary segments.
std::vector<Segment> convex_hull_segments(const Pslg& pslg);

// validate() with the domain options: a PSLG with no segments (a point set)
// meshes its convex hull, as Triangle does without -p; convex_hull adds the
// hull's segments to any PSLG; split_crossings splits crossing segments (see
// split_crossings()) instead of rejecting them.
Pslg validate(const Pslg& input, const DomainOptions& options, std::vector<std::string>& warnings);

// Splits every pair of properly crossing segments at their intersection, the
// exact point (CGAL exact constructions) rounded to the nearest doubles. The
// new vertices are appended after the input's; each segment is replaced in
// place by its pieces, first endpoint to second, and segment_origin maps each
// piece to the segment it came from. Repeats on the pieces (rounding can make
// new crossings) a few times. Input: vertices distinct, segments non-degenerate.
// Returns the number of vertices added.
std::size_t split_crossings(Pslg& pslg, std::vector<std::string>& warnings);

}  // namespace lepp
