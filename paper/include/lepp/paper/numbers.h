// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's own numbers: Table 1 (points added by Lepp-centroid and by Triangle
// on the four test problems) and the caption of Fig. 12 (Square400). They are the
// only constants of `lepp paper`: every other number on its page comes from a run.
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace lepp::paper {

// Table 1's angles, degrees, in its row order.
const std::vector<int>& table_angles();

struct PaperProblem {
  std::string key;    // file name in corpus/paper
  std::string name;   // as the paper calls it
  std::vector<int> centroid, triangle;  // Table 1, per table_angles(); -1: "-"
};

// Square400, Circles240, Rectangle162, A: Table 1's column order.
const std::vector<PaperProblem>& paper_problems();

// Fig. 12's caption: Square400, points added by each method at two angles.
struct Fig12Number {
  std::string method;
  int theta, points;
};
const std::vector<Fig12Number>& fig12_numbers();

// The paper's count of points added by `method` (centroid, midpoint, triangle)
// on `problem` (a corpus key) at `theta` degrees, or nullopt where it gives none.
std::optional<int> paper_number(const std::string& problem, const std::string& method, double theta);

}  // namespace lepp::paper
