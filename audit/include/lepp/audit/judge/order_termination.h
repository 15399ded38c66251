// SPDX-License-Identifier: GPL-3.0-or-later
// Is a termination difference the order or the method? For an audited run that
// ends where lepp's default order (fifo) does not, or the reverse, lepp's fast
// engine is run on the same input under every processing order (docs/ALGORITHM.md
// section 7): the orders that converge there tell the user whether lepp, with the
// other program's order, would have ended too.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lepp/audit/engine.h"
#include "lepp/pslg.h"
#include "lepp/refine.h"

namespace lepp::audit {

struct OrderTermination {
  std::string input;
  double theta = 0;
  bool engine_converged = false;         // the audited run ended with a mesh
  bool fifo_converged = false;           // lepp's default order converged
  std::vector<std::string> converging;   // lepp's named orders that converge
  int random_converged = 0, random_tried = 0;  // random orders, seeds 1..random_tried
};

// Whether an audited run's status says anything of its termination: it converged
// (Ok), or it did not (TimedOut, Stopped). A run that ended otherwise (a crash, a
// non-zero exit, an unreadable output) did end: its failure is its own row's, and
// "does not end" would contradict the termination row.
bool termination_comparable(RunStatus status);

// lepp under every order on `pslg` (a validated input) when fifo's termination
// differs from the engine's; nullopt when they agree. Each lepp run is bounded by
// lepp's default Steiner budget and `time_limit` seconds (a stop counts as not converging)
// and searches tie resolutions in at most tie_search_states Lepp states (RefineOptions).
std::optional<OrderTermination> compare_termination(const Pslg& pslg, const std::string& input, Method method, double theta,
                                                    bool engine_converged, double time_limit, int random_orders = 10,
                                                    std::size_t tie_search_states = kTieSearchStates);

// The report's paragraph (at most max_listed lines, then a count) and JSON.
std::string format_order_terminations(const std::vector<OrderTermination>& v, std::size_t max_listed);
nlohmann::json to_json(const std::vector<OrderTermination>& v);

}  // namespace lepp::audit
