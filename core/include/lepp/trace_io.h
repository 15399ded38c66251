// SPDX-License-Identifier: GPL-3.0-or-later
// PREFIX.trace: the Steiner points a mesher inserted, in insertion order, so
// that an audit can replay them on the exact reference (docs/FORMATS.md).
#pragma once
#include <string>
#include <vector>

#include "lepp/pslg.h"
#include "lepp/refine.h"

namespace lepp {

// Text, `#` comments, one `x y` per non-blank line; further fields ignored.
// Bad input throws lepp::InputError naming the file and line.
std::vector<Point> read_trace(const std::string& path);
// Writes one `x y` line per point with %.17g (the doubles round-trip exactly).
void write_trace(const std::string& path, const std::vector<Point>& points);
// The inserted points of an engine's trace (RefineResult::trace), in order: what PREFIX.trace lists.
std::vector<Point> trace_points(const std::vector<TraceStep>& steps);

}  // namespace lepp
