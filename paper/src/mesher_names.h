// SPDX-License-Identifier: GPL-3.0-or-later
// The study's meshers and orders as its runs name them, spelled by the engine registry.
#pragma once
#include "lepp/engines/registry.h"
#include "lepp/refine.h"

namespace lepp::paper {

// lepp's runs are named by their method, the peers' by their engine.
inline const char* centroid_name() { return to_string(Method::Centroid); }
inline const char* midpoint_name() { return to_string(Method::Midpoint); }
inline const char* triangle_name() { return engines::to_string(engines::Engine::Triangle); }
inline const char* cgal_name() { return engines::to_string(engines::Engine::Cgal); }
inline const char* fifo_name() { return to_string(QueueOrder::Fifo); }
inline const char* lifo_name() { return to_string(QueueOrder::Lifo); }

}  // namespace lepp::paper
