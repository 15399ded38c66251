// SPDX-License-Identifier: GPL-3.0-or-later
// The audit session: scratch directories, requests, progress (loop/session.h).
#include "loop/session.h"

#include <stdlib.h>

#include <filesystem>

#include <fmt/format.h>

#include "lepp/audit/run/parallel.h"
#include "loop/scratch_names.h"

namespace fs = std::filesystem;

namespace lepp::audit::loop {
namespace {

std::string make_work_root(const std::string& wanted) {
  if (!wanted.empty()) {
    fs::create_directories(wanted);
    return wanted;
  }
  std::string templ = (fs::temp_directory_path() / kScratchRootTemplate).string();
  if (!mkdtemp(templ.data())) throw UsageError("cannot create a scratch directory in " + fs::temp_directory_path().string());
  return templ;
}

}  // namespace

std::string Scratch::fresh() {
  const std::size_t w = worker_index();
  std::size_t k;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    k = counters_[w]++;
  }
  fs::path d = fs::path(root_) / run_dir_name(w, k % 4);
  std::error_code ec;
  fs::remove_all(d, ec);
  fs::create_directories(d, ec);
  return d.string();
}

AuditSession::AuditSession(const Engine& engine_, const AuditOptions& options_, std::size_t jobs_, std::size_t total_cases)
    : engine(engine_),
      options(options_),
      jobs(jobs_),
      cache(options_.points_cache_dir),
      work_root_(make_work_root(options_.work_dir)),
      own_work_root_(options_.work_dir.empty()),
      scratch_(work_root_),
      total_(total_cases) {}

EngineRequest AuditSession::request_for(double theta, double timeout_seconds) {
  EngineRequest r;
  r.method = options.method;
  r.theta = theta;
  r.timeout_seconds = timeout_seconds;
  r.memory_mb = options.memory_mb;
  r.work_dir = scratch_.fresh();
  return r;
}

void AuditSession::progress(const std::string& what) {
  if (!options.on_progress) return;
  std::lock_guard<std::mutex> lock(progress_mutex_);
  options.on_progress({done_.load(), total_, failing_.load(), what});
}

void AuditSession::case_done(bool failed) {
  ++done_;
  if (failed) ++failing_;
}

void AuditSession::progress_finished() {
  if (options.on_progress) options.on_progress({total_, total_, failing_.load(), ""});
}

void AuditSession::remove_own_work_root() {
  if (!own_work_root_) return;
  std::error_code ec;
  fs::remove_all(work_root_, ec);
}

}  // namespace lepp::audit::loop
