// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind lepp/paper/numbers.h: the paper's own numbers.
#include "lepp/paper/numbers.h"

#include "mesher_names.h"

namespace lepp::paper {

const std::vector<int>& table_angles() {
  static const std::vector<int> angles = {20, 25, 28, 30, 32, 34, 35, 36};
  return angles;
}

const std::vector<PaperProblem>& paper_problems() {
  static const std::vector<PaperProblem> problems = {
      {"square400", "Square400", {391, 491, 543, 595, 703, 919, 1264, 1843}, {310, 553, 557, 880, 1202, 1700, 1997, -1}},
      {"circles240", "Circles240", {274, 335, 371, 416, 493, 722, 911, 1630}, {202, 266, 386, 501, 639, 897, 1811, -1}},
      {"rect162", "Rectangle162", {217, 271, 286, 310, 363, 490, 570, 5473}, {156, 270, 277, 411, 592, 968, 4853, -1}},
      {"A", "A-case", {30, 43, 44, 49, 57, 85, 121, 239}, {27, 35, 45, 47, 63, 81, 112, -1}},
  };
  return problems;
}

const std::vector<Fig12Number>& fig12_numbers() {
  static const std::vector<Fig12Number> numbers = {
      {midpoint_name(), 10, 230}, {centroid_name(), 10, 185}, {midpoint_name(), 25, 668}, {centroid_name(), 25, 491}};
  return numbers;
}

std::optional<int> paper_number(const std::string& problem, const std::string& method, double theta) {
  if (problem == "square400" && (method == midpoint_name() || method == centroid_name()))
    for (const auto& f : fig12_numbers())
      if (f.method == method && f.theta == theta) return f.points;
  const std::vector<int>& angles = table_angles();
  for (const auto& p : paper_problems()) {
    if (p.key != problem) continue;
    for (std::size_t i = 0; i < angles.size(); ++i) {
      if (angles[i] != theta) continue;
      int v = method == centroid_name() ? p.centroid[i] : method == triangle_name() ? p.triangle[i] : -1;
      if (v >= 0) return v;
    }
  }
  return std::nullopt;
}

}  // namespace lepp::paper
