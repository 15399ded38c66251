// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind lepp/paper/summary_table.h: the plain-text table `lepp paper` prints
// on stdout.
#include "lepp/paper/summary_table.h"

#include <cstdarg>
#include <cstdio>

#include "lepp/paper/numbers.h"
#include "mesher_names.h"

namespace lepp::paper {
namespace {

// printf's formatting, into a string (the table's widths are printf's).
std::string printf_line(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string printf_line(const char* format, ...) {
  va_list args;
  va_start(args, format);
  va_list again;
  va_copy(again, args);
  int n = std::vsnprintf(nullptr, 0, format, args);
  va_end(args);
  std::string s(n > 0 ? static_cast<std::size_t>(n) : 0, '\0');
  if (n > 0) std::vsnprintf(s.data(), s.size() + 1, format, again);
  va_end(again);
  return s;
}

}  // namespace

std::string summary_table(const Results& res, const std::vector<double>& angles) {
  std::string out = printf_line("%-12s %-9s %5s %9s %7s %10s %s\n", "problem", "method", "theta", "steiner", "paper",
                                "min_angle", "outcome");
  for (const auto& p : paper_problems())
    for (const std::string method : {centroid_name(), midpoint_name(), triangle_name(), cgal_name()})
      for (double theta : angles) {
        const Run* r = res.find(p.key, method, theta);
        if (!r) continue;
        auto paper = paper_number(p.key, method, theta);
        out += printf_line("%-12s %-9s %5g %9lld %7s %10.3f %s\n", p.key.c_str(), method.c_str(), theta,
                           static_cast<long long>(r->steiner), paper ? std::to_string(*paper).c_str() : "",
                           r->stats.min_angle_deg, r->outcome.c_str());
      }
  return out;
}

}  // namespace lepp::paper
