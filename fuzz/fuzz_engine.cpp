// SPDX-License-Identifier: GPL-3.0-or-later
// fuzz_engine: loop hunting for any mesher. The structured PSLG input of
// fuzz_refine (support/fuzz_input.h) goes through an outside program given by a
// command template, run by the audit's command adapter (lepp/engines/command_engine.h):
//   LEPP_ENGINE_CMD='my-mesher {in} {out} {theta} {method}' fuzz/run.sh fuzz_engine 3600
// {in} is a .poly file, the program writes {out}.node and {out}.ele. Each run is
// decided by the audit's rows (lepp/audit/judge/checks.h): a run past the timeout or
// stopped short inside the band where the paper claims termination, a non-zero
// exit, a crash, unreadable output, a mesh that is not certified or has an angle
// below theta are findings and stop the fuzzer (the input is saved). A run that
// does not end, or ends with angles below theta, outside that band (midpoint
// above alpha_limit, centroid above 30, an input angle below 60 degrees), or
// stops short on an input with a feature below double resolution, is kept once
// per class and band in LEPP_FUZZ_KNOWN_DIR and the fuzzer goes on.
//
// Environment: LEPP_ENGINE_CMD (required), LEPP_ENGINE_TIMEOUT (seconds,
// default 10), LEPP_ENGINE_MEMORY_MB (address-space cap, default none),
// LEPP_ENGINE_WORK (scratch directory, default $TMPDIR), and fuzz_refine's
// LEPP_FUZZ_METHOD, LEPP_FUZZ_THETA, LEPP_FUZZ_MIN_INPUT_ANGLE, LEPP_FUZZ_IGNORE.
#include <cstdint>
#include <optional>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <unistd.h>

#include "lepp/audit/judge/checks.h"
#include "lepp/engines/command_engine.h"
#include "lepp/io.h"
#include "support/finding.h"
#include "support/fuzz_input.h"
#include "support/known_loops.h"
#include "support/loop_guard.h"
#include "support/pslg_mutator.h"

using namespace lepp::fuzz;
namespace audit = lepp::audit;
namespace fs = std::filesystem;

namespace {

double env_number(const char* name, double fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::atof(v) : fallback;
}

struct Setup {
  std::string command;
  audit::Engine engine;
  double timeout = 10;
  std::size_t memory_mb = 0;
  fs::path scratch;  // one directory per process; each run gets a fresh subdirectory
};

// Read once: a missing or bad template is a usage error (exit 2), not a finding.
const Setup& setup() {
  static const Setup s = [] {
    Setup r;
    const char* cmd = std::getenv("LEPP_ENGINE_CMD");
    if (!cmd || !*cmd) {
      std::fprintf(stderr, "fuzz_engine: set LEPP_ENGINE_CMD to a command template, e.g. "
                           "'my-mesher {in} {out} {theta} {method}' (docs/FUZZING.md)\n");
      std::exit(2);
    }
    r.command = cmd;
    try {
      r.engine = audit::command_engine(r.command);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "fuzz_engine: LEPP_ENGINE_CMD: %s\n", e.what());
      std::exit(2);
    }
    r.timeout = env_number("LEPP_ENGINE_TIMEOUT", 10);
    r.memory_mb = static_cast<std::size_t>(env_number("LEPP_ENGINE_MEMORY_MB", 0));
    const char* work = std::getenv("LEPP_ENGINE_WORK");
    r.scratch = fs::path(work && *work ? work : fs::temp_directory_path().string()) /
                fmt::format("lepp-fuzz-engine-{}", ::getpid());
    fs::create_directories(r.scratch);
    static const fs::path* scratch = new fs::path(r.scratch);  // outlives the statics at exit
    std::atexit([] {
      std::error_code ec;
      fs::remove_all(*scratch, ec);
    });
    return r;
  }();
  return s;
}

void finding(const std::string& cls, const std::string& what) { report_finding("fuzz_engine", cls, what); }

// The finding class of a failed row: how the run ended when it did not end
// well, else the row ("engine-timed-out", "engine-unreadable-output", "engine-min-angle").
std::string class_of(audit::Row row, const audit::EngineRun& run) {
  if (run.status != audit::RunStatus::Ok) return std::string("engine-") + audit::to_string(run.status);
  return std::string("engine-") + audit::row_key(row);
}

}  // namespace

LEPP_FUZZ_PSLG_MUTATOR

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Setup& s = setup();
  FuzzInput input = decode(data, size);
  apply_environment(input);
  const std::optional<lepp::Pslg> valid = valid_pslg(input);
  if (!valid) return 0;
  const lepp::Pslg& pslg = *valid;
  const double min_input_angle = input_features(pslg).min_input_angle_deg;
  if (const char* min = std::getenv("LEPP_FUZZ_MIN_INPUT_ANGLE"))
    if (min_input_angle < std::atof(min)) return 0;

  audit::EngineRequest request;
  request.method = input.method ? lepp::Method::Midpoint : lepp::Method::Centroid;
  request.theta = theta_deg(input);
  request.timeout_seconds = s.timeout;
  request.memory_mb = s.memory_mb;
  const fs::path dir = s.scratch / "run";
  fs::remove_all(dir);
  fs::create_directories(dir);
  request.work_dir = dir.string();

  const audit::EngineRun run = s.engine(pslg, request);
  const audit::CaseResult result = audit::check_run(pslg, request, run, {});
  std::string stderr_head = run.stderr_text.substr(0, 200);
  for (char& c : stderr_head)
    if (c == '\n') c = ' ';
  const std::string what = fmt::format("{} cmd=[{}] status={} seconds={:.3g} detail=[{}] stderr=[{}]", describe(input),
                                       s.command, audit::to_string(run.status), run.seconds, run.detail, stderr_head);

  // A failed row stops the run, except the faces of a loop the paper does not
  // claim away: a run that did not end at a small input angle (termination is
  // claimed only for inputs without one), a mesh with angles below theta where
  // termination is not claimed (the program gave up on its own guard and wrote
  // what it had, as Triangle and the test mesher do), and a run that did not end,
  // or said it stopped short, on an input doubles do not resolve (THEOREMS.md,
  // "Termination in doubles"). A program that exits 0 with angles below theta
  // there still claimed a converged mesh: a finding.
  const bool claimed = audit::termination_claimed(request.method, request.theta);
  const bool stopped_short = run.status == audit::RunStatus::TimedOut || run.status == audit::RunStatus::Stopped ||
                             (run.status == audit::RunStatus::Ok && run.exit_code != 0);
  const std::string below_resolution = stopped_short ? below_resolution_reason(pslg) : std::string();
  auto known_loop = [&](audit::Row row) {
    const bool loop_row = row == audit::Row::Termination || row == audit::Row::MinAngle;
    return (row == audit::Row::Termination && min_input_angle < 60) || (row == audit::Row::MinAngle && !claimed) ||
           (loop_row && !below_resolution.empty());
  };
  for (audit::Row row : audit::kAllRows) {
    const audit::RowResult& r = result[row];
    if (r.verdict == audit::Verdict::Failed && !known_loop(row))
      finding(class_of(row, run), fmt::format("{} row={}: {}", what, audit::row_key(row), r.detail));
  }
  for (audit::Row row : audit::kAllRows) {
    const audit::RowResult& r = result[row];
    if (r.verdict != audit::Verdict::Finding && !(r.verdict == audit::Verdict::Failed && known_loop(row))) continue;
    const std::string cls = class_of(row, run);
    const std::vector<std::uint8_t> baked = encode(input);  // replays without LEPP_FUZZ_METHOD/THETA
    std::string reason =
        unclaimed_loop_reason(request.method, request.theta, min_input_angle < 60 ? "small-angle-cascade" : "");
    if (reason.empty() && r.verdict == audit::Verdict::Failed) reason = below_resolution;
    if (reason.empty()) reason = "audit-finding";
    report_known_finding("fuzz_engine", cls, reason, known_finding_key("fuzz_engine", cls, request.method, request.theta),
                         fmt::format("{} row={}: {}", what, audit::row_key(row), r.detail), baked.data(),
                         baked.size());
    break;  // one report per run
  }
  fs::remove_all(dir);
  return 0;
}
