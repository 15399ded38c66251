// SPDX-License-Identifier: GPL-3.0-or-later
// A termination difference: which of lepp's processing orders end where the program did not.
#include "lepp/audit/judge/order_termination.h"

#include <fmt/format.h>

#include "lepp/fast.h"

namespace lepp::audit {
namespace {

bool converges(const Pslg& pslg, Method method, double theta, QueueOrder order, std::uint64_t seed, double time_limit,
               std::size_t tie_search_states) {
  RefineOptions o;
  o.tie_search_states = tie_search_states;
  o.method = method;
  o.min_angle_deg = theta;
  o.order = order;
  o.order_seed = seed;
  o.time_limit_seconds = time_limit;
  const Outcome out = fast::refine(pslg, o).outcome;
  return out == Outcome::Converged || out == Outcome::Unimprovable;
}

}  // namespace

bool termination_comparable(RunStatus status) {
  return status == RunStatus::Ok || status == RunStatus::TimedOut || status == RunStatus::Stopped;
}

std::optional<OrderTermination> compare_termination(const Pslg& pslg, const std::string& input, Method method, double theta,
                                                    bool engine_converged, double time_limit, int random_orders,
                                                    std::size_t tie_search_states) {
  OrderTermination t;
  t.input = input, t.theta = theta, t.engine_converged = engine_converged;
  t.fifo_converged = converges(pslg, method, theta, QueueOrder::Fifo, 0, time_limit, tie_search_states);
  if (t.fifo_converged == engine_converged) return std::nullopt;
  for (QueueOrder q : all_queue_orders()) {
    if (q == QueueOrder::Random) continue;
    if (q == QueueOrder::Fifo ? t.fifo_converged : converges(pslg, method, theta, q, 0, time_limit, tie_search_states))
      t.converging.push_back(to_string(q));
  }
  t.random_tried = random_orders;
  for (int s = 1; s <= random_orders; ++s)
    t.random_converged += converges(pslg, method, theta, QueueOrder::Random, static_cast<std::uint64_t>(s), time_limit, tie_search_states);
  return t;
}

std::string format_order_terminations(const std::vector<OrderTermination>& v, std::size_t max_listed) {
  if (v.empty()) return "";
  std::string md = fmt::format(
      "\nTermination against lepp's processing orders ({} runs where the engine {} lepp's default order, fifo; "
      "docs/ALGORITHM.md section 7): the lepp orders that converge there. An order that ends where the engine ends says "
      "the difference can be the order, not the method.\n\n",
      v.size(), "ends differently from");
  std::size_t listed = 0;
  for (const OrderTermination& t : v) {
    if (listed++ == max_listed) {
      md += fmt::format("- ... and {} more (JSON: `order_termination`)\n", v.size() - max_listed);
      break;
    }
    std::string orders;
    for (const std::string& o : t.converging) orders += (orders.empty() ? "" : ", ") + o;
    md += fmt::format("- {} at theta {:g}: the engine {}, lepp fifo {}; lepp converges with {}; random orders {}/{}\n", t.input,
                      t.theta, t.engine_converged ? "ends" : "does not end", t.fifo_converged ? "ends" : "does not end",
                      orders.empty() ? "no named order" : orders, t.random_converged, t.random_tried);
  }
  return md;
}

nlohmann::json to_json(const std::vector<OrderTermination>& v) {
  nlohmann::json a = nlohmann::json::array();
  for (const OrderTermination& t : v)
    a.push_back({{"input", t.input}, {"theta", t.theta}, {"engine_converged", t.engine_converged},
                 {"lepp_fifo_converged", t.fifo_converged}, {"lepp_orders_converging", t.converging},
                 {"random_converged", t.random_converged}, {"random_tried", t.random_tried}});
  return a;
}

}  // namespace lepp::audit
