// SPDX-License-Identifier: GPL-3.0-or-later
// Geometric checks and repairs of a parsed PSLG, before any engine sees it.
#pragma once
#include <string>
#include <vector>

#include "lepp/pslg.h"

namespace lepp {

// Makes a PSLG an engine can triangulate without Steiner points, or throws
// InputError naming the file and line:
//  - NaN or infinite coordinates: error;
//  - duplicate vertices (exactly equal coordinates): merged, warning;
//  - segments with equal endpoints (after merging): error (zero-length segment);
//  - repeated segments: dropped, warning;
//  - a vertex in the interior of a segment: the segment is split there, warning;
//  - two segments crossing: error naming both segment numbers;
//  - fewer than three non-collinear vertices: error;
//  - a hole point outside the domain or on a segment: warning (it removes nothing);
//  - a region point with an area bound outside the domain, in a hole, on a segment
//    or on a vertex: warning (its bound applies to nothing).
// Ids in the result are 0-based and dense; lines are kept for later messages.
Pslg validate(const Pslg& input, std::vector<std::string>& warnings);

}  // namespace lepp
