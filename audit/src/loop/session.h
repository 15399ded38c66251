// SPDX-License-Identifier: GPL-3.0-or-later
// What every step of run_audit shares (private to lepp_audit): the engine and
// the options, the scratch directories the runs write in, the comparison
// points cache, and the progress line.
#pragma once
#include <atomic>
#include <chrono>
#include <cstddef>
#include <map>
#include <mutex>
#include <string>

#include "lepp/audit/audit.h"
#include "lepp/audit/inputs/points_cache.h"

namespace lepp::audit::loop {

using Clock = std::chrono::steady_clock;
inline double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Scratch directories for the runs, emptied before each: a few per thread
// (worker_index()), reused in turn so a long audit does not fill the disk.
class Scratch {
 public:
  explicit Scratch(std::string root) : root_(std::move(root)) {}
  std::string fresh();

 private:
  std::string root_;
  std::mutex mutex_;
  std::map<std::size_t, std::size_t> counters_;
};

class AuditSession {
 public:
  // Makes the scratch root (--work-dir, or a fresh one under the system temp dir).
  AuditSession(const Engine& engine, const AuditOptions& options, std::size_t jobs, std::size_t total_cases);

  const Engine& engine;
  const AuditOptions& options;
  const std::size_t jobs;            // -j resolved
  const PointsCache cache;

  // A request at theta with this timeout, in a fresh scratch directory.
  EngineRequest request_for(double theta, double timeout_seconds);

  // The progress line: what is being done now, and a case finished (failed: some row failed on it).
  void progress(const std::string& what);
  void case_done(bool failed);
  void progress_finished();

  // Removes the scratch root when the session made it (not a --work-dir).
  void remove_own_work_root();

 private:
  const std::string work_root_;
  const bool own_work_root_;
  Scratch scratch_;
  const std::size_t total_;
  std::mutex progress_mutex_;
  std::atomic<std::size_t> done_{0}, failing_{0};
};

}  // namespace lepp::audit::loop
