// SPDX-License-Identifier: GPL-3.0-or-later
// One run of one mesher on one input at one angle: our Lepp engines, CGAL's
// mesher (engines/others/cgal_mesher.h) and Triangle (engines/others/triangle_wasm.h), each
// recorded as a Run with its mesh written under OPTIONS.work/meshes/.
#pragma once
#include <string>
#include <vector>

#include "lepp/engines/registry.h"
#include "lepp/mesh.h"
#include "lepp/paper/options.h"
#include "lepp/paper/run.h"
#include "lepp/pslg.h"
#include "lepp/refine.h"

namespace lepp::paper {

// Area quality q of every triangle in 20 bins of width 0.05 (Fig. 12).
std::vector<int> quality_histogram(const Mesh& mesh);

class Runner {
 public:
  // Keeps a reference to `options`: it must outlive the runner.
  explicit Runner(const Options& options) : options_(options) {}

  // The engine the options name (auto: fast), by the registry (lepp/engines/registry.h).
  RefineResult refine(const Pslg& pslg, const RefineOptions& options);
  // The engine of the last refine (the reference before any).
  const std::string& engine() const { return engine_; }

  // method: centroid or midpoint; order: a processing order's name. An engine's exception
  // becomes the outcome "engine error: ...".
  Run lepp_run(const std::string& problem, const std::string& reading, const Pslg& pslg, const std::string& method,
               double theta, const std::string& order = to_string(QueueOrder::Fifo));
  Run cgal_run(const std::string& problem, const std::string& reading, const Pslg& pslg, double theta);
  // poly: the file Triangle reads (the same input as pslg).
  Run triangle_run(const std::string& problem, const std::string& reading, const std::string& poly, const Pslg& pslg,
                   double theta);

  // node and triangle-wasm are installed under OPTIONS.root.
  bool triangle_available() const;

 private:
  Run start(const std::string& problem, const std::string& reading, const std::string& method, double theta) const;
  void finish(Run& r, const Mesh& mesh, const Pslg& pslg) const;

  const Options& options_;
  std::string engine_ = engines::to_string(engines::Engine::Reference);
};

}  // namespace lepp::paper
