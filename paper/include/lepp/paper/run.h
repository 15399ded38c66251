// SPDX-License-Identifier: GPL-3.0-or-later
// The record of one run of one mesher on one input at one angle, and the runs of
// a study, found by what was run.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lepp/refine.h"
#include "lepp/stats.h"

namespace lepp::paper {

// Triangle and CGAL decide "bad" in floating point; a smallest angle this far
// below theta (degrees) still counts as meeting it.
constexpr double kAngleSlack = 1e-3;

struct Run {
  std::string problem;   // corpus key, or reading name
  std::string reading;   // "" for the corpus file, else the reading's file stem
  std::string method;    // centroid, midpoint, triangle, cgal
  std::string order = to_string(QueueOrder::Fifo);
  double theta = 0;
  std::int64_t steiner = 0;
  bool finished = false;
  std::string outcome;   // converged, or why not
  MeshStats stats;
  double avg_lepp = 0;
  double seconds = 0;
  std::vector<int> q_hist;  // area quality q in 20 bins of width 0.05
  std::string mesh_prefix;
};

// A run with its keys set (what Results::find looks for, order fifo), nothing measured yet.
Run keyed_run(const std::string& problem, const std::string& reading, const std::string& method, double theta);

// One entry of results.json's "runs" (paper/plots.py reads these keys).
nlohmann::json to_json(const Run& r);

class Results {
 public:
  void add(const Run& r) { runs_.push_back(r); }
  const std::vector<Run>& runs() const { return runs_; }
  // The first run with these keys, or nullptr.
  const Run* find(const std::string& problem, const std::string& method, double theta,
                  const std::string& order = to_string(QueueOrder::Fifo), const std::string& reading = "") const;

 private:
  std::vector<Run> runs_;
};

}  // namespace lepp::paper
