// SPDX-License-Identifier: GPL-3.0-or-later
// The engine under audit, seen from the audit: a callable from a validated
// PSLG and a request (method, theta, limits, a directory to work in) to what
// came out (a mesh, an optional trace, how the run ended). The command adapter
// and lepp's own engines (engines/: lepp/engines/command_engine.h, builtin_engines.h)
// and the peers (peer_engines.h) all have this shape, and so can any C++ engine
// (examples/audit_engine).
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "lepp/mesh.h"
#include "lepp/pslg.h"
#include "lepp/refine.h"

namespace lepp::audit {

struct EngineRequest {
  Method method = Method::Centroid;
  double theta = 30;               // smallest angle asked for, degrees
  double timeout_seconds = 10;     // a run past this is killed (or asked to stop): non-termination
  std::size_t memory_mb = 0;       // address-space cap of a subprocess; 0: none
  std::string work_dir;            // an empty directory the engine may write into
};

// How a run ended. Only Ok runs have a mesh to certify.
enum class RunStatus {
  Ok,                // finished, mesh read
  ExitCode,          // the program exited with a non-zero status
  Crashed,           // killed by a signal (not ours), or an in-process engine threw
  TimedOut,          // still running at the timeout: killed
  Stopped,           // the engine stopped itself before converging (a Steiner budget, an edge floor)
  UnreadableOutput,  // exited 0 but its output files are missing or malformed
};

const char* to_string(RunStatus status);

struct EngineRun {
  RunStatus status = RunStatus::Ok;
  Mesh mesh;                                  // valid when status == Ok (and for Stopped runs that kept one)
  std::optional<std::vector<Point>> trace;    // Steiner points in insertion order, when the engine gives them
  int exit_code = 0;                          // ExitCode: the status
  int signal = 0;                             // Crashed by a signal: its number
  std::string detail;                         // one line: why not Ok (parse error, exception, outcome)
  std::string stderr_text;                    // what the program wrote on stderr, capped
  double seconds = 0;                         // wall-clock time of the engine alone
  std::vector<std::string> output_files;      // files the engine left in work_dir (kept with a finding)
};

// Any engine: must not throw for anything the input or the program does
// (adapters turn failures into a RunStatus); may throw UsageError before the first run.
using Engine = std::function<EngineRun(const Pslg& validated, const EngineRequest& request)>;

// Bad usage of the audit itself (unknown placeholder, program not found, missing
// input directory): the CLI exits 2 with this one-line message.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace lepp::audit
