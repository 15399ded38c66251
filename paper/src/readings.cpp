// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind lepp/paper/readings.h: alternative readings of the problems whose
// geometry the paper does not pin down (Circles240, Rectangle162).
#include "lepp/paper/readings.h"

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace lepp::paper {

std::vector<Reading> find_readings(const std::string& root) {
  std::vector<Reading> readings;
  fs::path dir = fs::path(root) / "paper" / "readings";
  if (!fs::is_directory(dir)) return readings;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".poly") continue;
    Reading r;
    r.stem = entry.path().stem().string();
    r.path = entry.path().string();
    r.problem = r.stem.substr(0, r.stem.find('-'));
    std::ifstream in(r.path);
    std::string first;
    std::getline(in, first);
    // A bare "#" line describes nothing (and must not throw).
    auto text = first.rfind("#", 0) == 0 ? first.find_first_not_of("# ") : std::string::npos;
    r.description = text == std::string::npos ? "" : first.substr(text);
    if (auto colon = r.description.find(": "); colon != std::string::npos) r.description = r.description.substr(colon + 2);
    readings.push_back(r);
  }
  std::sort(readings.begin(), readings.end(), [](const Reading& a, const Reading& b) { return a.stem < b.stem; });
  return readings;
}

}  // namespace lepp::paper
