// SPDX-License-Identifier: GPL-3.0-or-later
// How our runs compare with the paper's numbers and with each other: the
// distance of a column to the paper's, and the angle up to which a method works.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "lepp/paper/run.h"

namespace lepp::paper {

struct Gap {
  double median = 0;  // median of |ours - paper| / paper
  int angles = 0;     // over this many Table 1 angles
};

// Median of |ours - paper| / paper over the Table 1 angles where our fifo run of
// `method` on `problem` (or on its `reading`) finished and the paper gives a
// number (a median, so that one runaway angle, 36 degrees say, does not hide the
// rest); nullopt when there is no such angle.
std::optional<Gap> median_relative_gap(const Results& res, const std::string& problem, const std::string& method,
                                       const std::string& reading);

// The highest angle of `angles` (ascending) up to which every run of the method
// finished with no angle below it (missing runs skipped; the first run that did
// not stops the count), or nullopt.
std::optional<double> converges_up_to(const Results& res, const std::string& problem, const std::string& method,
                                      const std::vector<double>& angles);

}  // namespace lepp::paper
