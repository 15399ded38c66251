// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind lepp/paper/measures.h: how our runs compare with the paper's numbers
// and with each other.
#include "lepp/paper/measures.h"

#include <algorithm>
#include <cmath>

#include "lepp/paper/numbers.h"
#include "mesher_names.h"

namespace lepp::paper {

std::optional<Gap> median_relative_gap(const Results& res, const std::string& problem, const std::string& method,
                                       const std::string& reading) {
  std::vector<double> gaps;
  for (int theta : table_angles()) {
    const Run* r = res.find(problem, method, theta, fifo_name(), reading);
    auto p = paper_number(problem, method, theta);
    if (!r || !p || !r->finished) continue;
    gaps.push_back(std::abs(static_cast<double>(r->steiner - *p)) / *p);
  }
  if (gaps.empty()) return std::nullopt;
  std::sort(gaps.begin(), gaps.end());
  std::size_t n = gaps.size();
  return Gap{n % 2 ? gaps[n / 2] : (gaps[n / 2 - 1] + gaps[n / 2]) / 2, static_cast<int>(n)};
}

std::optional<double> converges_up_to(const Results& res, const std::string& problem, const std::string& method,
                                      const std::vector<double>& angles) {
  std::optional<double> best;
  for (double theta : angles) {
    const Run* r = res.find(problem, method, theta);
    if (!r) continue;
    if (!r->finished || r->stats.min_angle_deg < theta - kAngleSlack) break;
    best = theta;
  }
  return best;
}

}  // namespace lepp::paper
