// SPDX-License-Identifier: GPL-3.0-or-later
// `lepp refine`'s request: what it is asked, as typed, checked before anything is read,
// and turned into the engine's RefineOptions. With refine_files.h and refine_summary.h,
// `lepp refine` as a library: a caller fills a RefineRequest and gets the same files and report.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "lepp/engines/registry.h"
#include "lepp/refine.h"
#include "lepp/input.h"

namespace lepp::engines {

// Every option of `lepp refine`, the names spelled as the registry spells them.
struct RefineRequest {
  std::string input, output;  // the .poly/.node (or bare prefix) read; the output prefix
  double min_angle = 30;
  std::string method = lepp::to_string(Method::Centroid);
  std::string engine = to_string(Engine::Fast);  // one of lepp_engines()
  std::string order = lepp::to_string(QueueOrder::Fifo);
  std::uint64_t order_seed = 0;
  int threads = 0;
  std::int64_t max_steiner = -1;
  double max_area = 0;
  bool region_areas = false;
  double time_limit = 0;
  double edge_floor = -1;
  std::size_t tie_search_states = kTieSearchStates;  // RefineOptions::tie_search_states
  bool json = false;
  bool quiet = false;
  bool trace = false;
  std::vector<std::string> formats{"triangle"};  // --format replaces it
  bool binary = false;                           // .msh in Gmsh's binary variant
  DomainOptions domain;
};

// Why the request cannot run, as `lepp refine` says it (exit 2), or "": an output
// prefix that would write over the input read, or msh2 and msh4 both asked (each
// writes PREFIX.msh). Checked before reading, so nothing is read or written.
std::string refine_request_error(const RefineRequest& request);

// The engine's options (no progress callback: printing one is the caller's).
// Throws std::invalid_argument for a method or order the registry does not name.
RefineOptions refine_options(const RefineRequest& request);

// lepp's engine named by request.engine. Throws std::invalid_argument for another name.
Engine refine_engine(const RefineRequest& request);

}  // namespace lepp::engines
