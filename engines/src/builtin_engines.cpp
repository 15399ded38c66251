// SPDX-License-Identifier: GPL-3.0-or-later
// lepp's engines as audit engines: options in, mesh, trace and status out.
#include "lepp/engines/builtin_engines.h"

#include <chrono>
#include <exception>

namespace lepp::engines {

audit::Engine lepp_audit_engine(Engine which, QueueOrder order, std::size_t tie_search_states) {
  return audit::refine_engine(refine_function(which), order, tie_search_states);
}

}  // namespace lepp::engines

namespace lepp::audit {

Engine refine_engine(RefineFunction refine, QueueOrder order, std::size_t tie_search_states) {
  return [refine, order, tie_search_states](const Pslg& pslg, const EngineRequest& req) {
    EngineRun run;
    RefineOptions o;
    o.min_angle_deg = req.theta;
    o.method = req.method;
    o.order = order;
    o.tie_search_states = tie_search_states;
    o.trace = true;
    o.time_limit_seconds = req.timeout_seconds > 0 ? req.timeout_seconds : 0;
    const auto t0 = std::chrono::steady_clock::now();
    try {
      RefineResult r = refine(pslg, o);
      run.mesh = std::move(r.mesh);
      std::vector<Point> trace;
      trace.reserve(r.trace.size());
      for (const TraceStep& s : r.trace) trace.push_back(s.point);
      run.trace = std::move(trace);
      switch (r.outcome) {
        case Outcome::Converged:
        case Outcome::Unimprovable:
          run.status = RunStatus::Ok;
          break;
        case Outcome::TimeLimit:
          run.status = RunStatus::TimedOut;
          run.detail = "stopped by its time limit (the audit's timeout)";
          break;
        default:
          run.status = RunStatus::Stopped;
          run.detail = std::string("stopped by a guard: ") + to_string(r.outcome) + (r.stuck.empty() ? "" : " (" + r.stuck + ")");
          break;
      }
    } catch (const std::exception& e) {
      run.status = RunStatus::Crashed;
      run.detail = std::string("exception: ") + e.what();
    }
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return run;
  };
}

Engine reference_points_engine(std::size_t tie_search_states) {
  Engine reference = reference_engine(QueueOrder::Fifo, tie_search_states);
  return [reference, tie_search_states](const Pslg& pslg, const EngineRequest& req) {
    RefineOptions o;
    o.min_angle_deg = req.theta;
    o.method = req.method;
    o.tie_search_states = tie_search_states;
    o.time_limit_seconds = req.timeout_seconds > 0 ? req.timeout_seconds : 0;
    const auto t0 = std::chrono::steady_clock::now();
    try {
      RefineResult r = engines::refine(engines::Engine::Fast, pslg, o);
      if (r.cocircular_ties == 0 && (r.outcome == Outcome::Converged || r.outcome == Outcome::Unimprovable)) {
        EngineRun run;
        run.mesh = std::move(r.mesh);
        run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        return run;
      }
    } catch (const std::exception&) {
      // the reference decides
    }
    EngineRun run = reference(pslg, req);
    run.trace.reset();
    return run;
  };
}

Engine fast_engine(QueueOrder order, std::size_t tie_search_states) {
  return engines::lepp_audit_engine(engines::Engine::Fast, order, tie_search_states);
}
Engine reference_engine(QueueOrder order, std::size_t tie_search_states) {
  return engines::lepp_audit_engine(engines::Engine::Reference, order, tie_search_states);
}

}  // namespace lepp::audit
