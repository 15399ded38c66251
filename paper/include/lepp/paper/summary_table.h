// SPDX-License-Identifier: GPL-3.0-or-later
// The plain-text table `lepp paper` prints on stdout: one line per run on the
// corpus problems (fifo), with the paper's number where it gives one.
#pragma once
#include <string>
#include <vector>

#include "lepp/paper/run.h"

namespace lepp::paper {

// A header line, then the runs by problem, method (centroid, midpoint,
// triangle, cgal) and angle of `angles`; every line ends in '\n'.
std::string summary_table(const Results& res, const std::vector<double>& angles);

}  // namespace lepp::paper
