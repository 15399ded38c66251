// SPDX-License-Identifier: GPL-3.0-or-later
// lepp's own engines as audit engines, in process, with their trace points:
// fast (lepp::fast) and reference (lepp::reference), chosen in the registry. The timeout becomes the
// engine's wall-clock limit; a run stopped by a guard (Steiner budget, edge
// floor, time limit) is RunStatus::Stopped (TimedOut for the time limit).
#pragma once
#include <cstddef>
#include <string>

#include "lepp/audit/engine.h"
#include "lepp/engines/registry.h"

namespace lepp::engines {

// lepp's engine WHICH (fast or reference: is_lepp_engine) as an audit engine, its
// search of tie resolutions bounded by tie_search_states (RefineOptions; the audit's
// --tie-search-states, which its certificate uses too).
audit::Engine lepp_audit_engine(Engine which, QueueOrder order = QueueOrder::Fifo,
                                std::size_t tie_search_states = kTieSearchStates);

}  // namespace lepp::engines

namespace lepp::audit {

Engine fast_engine(QueueOrder order = QueueOrder::Fifo, std::size_t tie_search_states = kTieSearchStates);
Engine reference_engine(QueueOrder order = QueueOrder::Fifo, std::size_t tie_search_states = kTieSearchStates);

// Adapts any function with lepp's refine signature (for C++ engines built on lepp's types).
using RefineFunction = engines::RefineFunction;
Engine refine_engine(RefineFunction refine, QueueOrder order = QueueOrder::Fifo,
                     std::size_t tie_search_states = kTieSearchStates);

// The reference engine's mesh for the points comparison (`--compare reference`),
// made by the fast engine where the two are identical (docs/ALGORITHM.md: the
// same mesh when neither meets four cocircular points; the audit's tests check
// it on the audit's inputs) and by the reference where the fast run met a
// cocircular tie or did not end normally. No trace.
Engine reference_points_engine(std::size_t tie_search_states = kTieSearchStates);

}  // namespace lepp::audit
