// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind lepp/paper/cells.h: the cells of PAPER.md's tables.
#include "lepp/paper/cells.h"

#include <fmt/format.h>

namespace lepp::paper {

std::string points_cell(const Run* r) {
  if (!r) return "";
  if (!r->finished && r->outcome.rfind("engine error", 0) == 0) return "n/a";
  if (!r->finished && r->steiner == 0 && r->stats.triangles == 0) return "failed";
  if (!r->finished) {
    // Why it stopped: our guards by name, the others' budget as "dnf".
    std::string why = r->outcome == "steiner-budget" ? "budget"
                      : r->outcome == "edge-floor"   ? "edge floor"
                      : r->outcome == "time-limit"   ? "time"
                                                     : "dnf";
    return fmt::format("> {} ({})", r->steiner, why);
  }
  // Finished by the method's own rule with angles left below theta (CGAL near
  // small input angles, our unimprovable triangles): marked, not hidden.
  if (r->stats.min_angle_deg < r->theta - kAngleSlack) return fmt::format("{} †", r->steiner);
  return std::to_string(r->steiner);
}

std::string difference_cell(const Run* r, std::optional<int> paper) {
  if (!r || !paper || !r->finished) return "";
  double d = static_cast<double>(r->steiner - *paper);
  return fmt::format("{:+.0f} ({:+.0f}%)", d, 100.0 * d / *paper);
}

}  // namespace lepp::paper
