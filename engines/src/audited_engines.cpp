// SPDX-License-Identifier: GPL-3.0-or-later
// The audit's engines by name: the engine under audit and the comparisons.
#include "lepp/engines/audited_engines.h"

#include <stdexcept>
#include <string>

#include "lepp/audit/run/isolated_engine.h"
#include "lepp/engines/builtin_engines.h"
#include "lepp/engines/peer_engines.h"
#include "lepp/version.h"

namespace lepp::engines {
namespace {

// lepp's engines run in a child unless the caller wants them in process (a debugger, a sanitizer).
audit::Engine maybe_isolated(audit::Engine engine, bool isolate) {
  return isolate ? audit::isolated_engine(std::move(engine)) : engine;
}

}  // namespace

audit::Engine audited_engine(Engine which, QueueOrder order, bool isolate, const std::string& root,
                             std::size_t tie_search_states) {
  switch (which) {
    case Engine::Fast:
    case Engine::Reference: return maybe_isolated(lepp_audit_engine(which, order, tie_search_states), isolate);
    case Engine::Triangle: return audit::triangle_engine(root);
    case Engine::Cgal: return audit::cgal_engine();
    case Engine::Command: break;
  }
  throw std::invalid_argument("a command engine is made from its template (command_engine.h)");
}

audit::NamedEngine comparison_engine(Engine which, bool isolate, const std::string& root, const std::string& build,
                                     std::size_t tie_search_states) {
  const std::string title = comparison_title(which);
  // Another bound may give other points: another cache entry (the default's keys are as they were).
  const std::string ties = tie_search_states == kTieSearchStates ? "" : " tie-search-states " + std::to_string(tie_search_states);
  switch (which) {
    case Engine::Reference:
      return {title, maybe_isolated(audit::reference_points_engine(tie_search_states), isolate), "lepp-reference " + build + ties};
    case Engine::Fast:
      return {title, maybe_isolated(audit::fast_engine(QueueOrder::Fifo, tie_search_states), isolate), "lepp-fast " + build + ties};
    case Engine::Cgal: return {title, audit::cgal_engine(), "cgal " + std::string(cgal_version())};
    case Engine::Triangle: return {title, audit::triangle_engine(root), "triangle-wasm -S20000 " + build};
    case Engine::Command: break;
  }
  throw std::invalid_argument("a command engine is no comparison");
}

}  // namespace lepp::engines
