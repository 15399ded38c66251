// SPDX-License-Identifier: GPL-3.0-or-later
// The audit's engines by name: the engine under audit (`lepp audit --engine NAME`)
// and the comparisons (--compare NAME), each as the registry names it. Part of
// lepp_peer_engines (Triangle and CGAL; not in the find_package package).
#pragma once
#include <cstddef>
#include <string>

#include "lepp/audit/audit.h"
#include "lepp/audit/engine.h"
#include "lepp/engines/registry.h"

namespace lepp::engines {

// The engine under audit: lepp's own with ORDER and TIE_SEARCH_STATES (in a child process
// when ISOLATE), Triangle (from ROOT's tools/triangle; throws audit::UsageError when
// missing) or CGAL (always in a child). Not Engine::Command: command_engine.h.
audit::Engine audited_engine(Engine which, QueueOrder order, bool isolate, const std::string& root,
                             std::size_t tie_search_states = kTieSearchStates);

// A comparison of `lepp audit`: its title, engine and points-cache key. `build` names
// lepp's build (version and commit) in the keys of lepp's engines and Triangle's; lepp's
// engines run with TIE_SEARCH_STATES, named in their keys when it is not the default.
// The reference is counted by reference_points_engine (builtin_engines.h).
audit::NamedEngine comparison_engine(Engine which, bool isolate, const std::string& root, const std::string& build,
                                     std::size_t tie_search_states = kTieSearchStates);

}  // namespace lepp::engines
