// SPDX-License-Identifier: GPL-3.0-or-later
// What the conformance tests share: the options of a traced run of lepp's
// engines, whose points the replay then judges.
#pragma once
#include <cstdint>

#include "lepp/refine.h"

namespace lepp::audit::test {

// Refinement at theta with `method`, in `order`, recording the trace, within a Steiner budget.
inline RefineOptions traced_options(Method method, QueueOrder order, double theta, std::int64_t max_steiner) {
  RefineOptions o;
  o.min_angle_deg = theta;
  o.method = method;
  o.order = order;
  o.trace = true;
  o.max_steiner = max_steiner;
  return o;
}

}  // namespace lepp::audit::test
