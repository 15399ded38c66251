// SPDX-License-Identifier: GPL-3.0-or-later
// Triangle (triangle-wasm under node) and CGAL's mesher as audit engines.
#include "lepp/engines/peer_engines.h"

#include <chrono>
#include <exception>
#include <filesystem>
#include <map>
#include <memory>

#include <fmt/format.h>

#include "cgal_mesher.h"
#include "lepp/engines/command_engine.h"
#include "lepp/audit/run/isolated_engine.h"
#include "lepp/io.h"
#include "triangle_wasm.h"

namespace lepp::audit {

Engine triangle_engine(const std::string& root, std::int64_t budget) {
  if (!others::triangle_available(root))
    throw UsageError("--engine triangle: needs node and tools/triangle/node_modules (run `npm ci` in " + root +
                     "/tools/triangle, as scripts/install-deps.sh does)");
  return [root, budget](const Pslg& pslg, const EngineRequest& req) {
    EngineRun run;
    std::string in, out;
    if (!write_engine_input(pslg, req, in, out, run)) return run;
    // One node process per thread, fed every case (others::TriangleServer).
    thread_local std::map<std::string, std::unique_ptr<others::TriangleServer>> servers;
    auto& server = servers[root];
    if (!server) server = std::make_unique<others::TriangleServer>(root);
    const others::TriangleRun tr = server->run(in, req.theta, budget, out, req.timeout_seconds);
    run.seconds = tr.seconds;
    for (const char* ext : {".node", ".ele", ".poly"})
      if (std::filesystem::exists(out + ext)) run.output_files.push_back(out + ext);
    if (tr.status == 0) {
      try {
        run.mesh = read_mesh(out);
      } catch (const std::exception& e) {
        run.status = RunStatus::UnreadableOutput;
        run.detail = e.what();
      }
    } else if (tr.status < 0) {
      const bool killed = tr.output.rfind("killed after", 0) == 0;
      run.status = killed ? RunStatus::TimedOut : RunStatus::Crashed;
      run.detail = tr.output;
    } else {
      run.status = RunStatus::ExitCode;
      run.exit_code = tr.status;
      run.detail = fmt::format("exit status {}: {}", tr.status, tr.output);
    }
    if (run.status == RunStatus::Ok &&
        static_cast<std::int64_t>(run.mesh.vertices.size()) - static_cast<std::int64_t>(pslg.vertices.size()) >= budget) {
      run.status = RunStatus::Stopped;
      run.detail = "used up Triangle's Steiner budget (-S)";
    }
    return run;
  };
}

Engine cgal_engine(std::int64_t budget) {
  // CGAL looks at the clock only between refinement steps (engines/others/cgal_mesher.cpp),
  // and a failed CGAL assertion aborts: in a child, the timeout and a crash end the
  // run, not the audit.
  return isolated_engine([budget](const Pslg& pslg, const EngineRequest& req) {
    EngineRun run;
    const auto t0 = std::chrono::steady_clock::now();
    try {
      others::CgalMeshLimits limits;
      limits.max_steiner = budget;
      limits.time_limit_seconds = req.timeout_seconds;
      others::CgalMeshResult r = others::cgal_mesh(pslg, req.theta, 0, limits);
      run.mesh = std::move(r.mesh);
      run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (!r.finished) {
        bool timed_out = req.timeout_seconds > 0 && run.seconds >= req.timeout_seconds;
        run.status = timed_out ? RunStatus::TimedOut : RunStatus::Stopped;
        run.detail = timed_out ? "stopped at the timeout" : "used up the Steiner budget";
      }
    } catch (const std::exception& e) {
      run.status = RunStatus::Crashed;
      run.detail = std::string("exception: ") + e.what();
      run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    return run;
  });
}

}  // namespace lepp::audit
