// SPDX-License-Identifier: GPL-3.0-or-later
// `lepp audit --engine fast|reference --order X` audits the order asked for (issue 42):
// the engine `lepp audit` makes from its options (audit_setup), isolated in a child
// and in process, runs lepp's refine under that order, not fifo, while the report
// names it. The input is one whose trace differs by order, so a setup that dropped
// the order on any link (the option, the registry, the engine's RefineOptions) is
// seen. The method and theta of each run reach the engine too. Kills
// engines-audit-order-dropped-in-refine-engine, engines-audit-order-dropped-in-registry,
// engines-audit-order-dropped-in-setup and engines-audit-method-dropped.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lepp/engines/audit_setup.h"
#include "lepp/engines/registry.h"
#include "lepp/io.h"
#include "lepp/validate.h"

namespace lepp::engines {
namespace {

Pslg square400() {
  std::vector<std::string> warnings;
  return validate(read_poly(std::string(LEPP_SOURCE_DIR) + "/corpus/paper/square400.poly"), warnings);
}

std::vector<Point> refine_trace(Engine engine, const Pslg& p, Method method, double theta, QueueOrder order) {
  RefineOptions o;
  o.min_angle_deg = theta;
  o.method = method;
  o.order = order;
  o.trace = true;
  std::vector<Point> out;
  for (const TraceStep& s : refine(engine, p, o).trace) out.push_back(s.point);
  return out;
}

audit::AuditRequest request(const std::string& engine, QueueOrder order, bool isolate) {
  audit::AuditRequest a;
  a.engine = engine;
  a.order = to_string(order);
  a.no_isolate = !isolate;
  a.compare = "none";
  a.no_cache = true;
  a.root = LEPP_SOURCE_DIR;
  return a;
}

TEST(AuditOrder, EveryOrderReachesTheEngineAndTheReport) {
  const Pslg p = square400();
  const double theta = 20;  // inside both methods' bands: every run converges
  for (Engine engine : {Engine::Fast, Engine::Reference}) {
    for (Method method : all_methods()) {
      const std::vector<Point> fifo = refine_trace(engine, p, method, theta, QueueOrder::Fifo);
      for (QueueOrder order : audit_orders()) {
        if (order == QueueOrder::Fifo) continue;
        const std::vector<Point> expected = refine_trace(engine, p, method, theta, order);
        // The premise: this input's trace tells the order apart.
        ASSERT_NE(expected, fifo) << to_string(engine) << " " << to_string(method) << " " << to_string(order);
        for (bool isolate : {true, false}) {
          SCOPED_TRACE(std::string(to_string(engine)) + " " + to_string(method) + " --order " + to_string(order) +
                       (isolate ? "" : " --no-isolate"));
          const AuditSetup setup = audit_setup(request(to_string(engine), order, isolate));
          audit::EngineRequest r;
          r.method = method;
          r.theta = theta;
          r.timeout_seconds = 60;
          const audit::EngineRun run = setup.engine(p, r);
          ASSERT_EQ(run.status, audit::RunStatus::Ok) << run.detail;
          ASSERT_TRUE(run.trace.has_value());
          EXPECT_EQ(*run.trace, expected);
          // The report and the findings' reproduce line say the same order.
          EXPECT_NE(setup.options.engine_name.find(std::string("(") + to_string(order) + ")"), std::string::npos)
              << setup.options.engine_name;
          EXPECT_NE(setup.options.reproduce_prefix.find(std::string("--order ") + to_string(order)), std::string::npos)
              << setup.options.reproduce_prefix;
        }
      }
    }
  }
}

// The run's timeout reaches lepp's engine in process as its own time limit (the only
// limit there: nothing kills an engine run in the audit's process), so the run
// stops itself and says so. Kills engines-audit-time-limit-dropped.
TEST(AuditOrder, TheTimeoutReachesTheEngineInProcess) {
  const Pslg p = square400();
  for (const char* engine : {"fast", "reference"}) {
    SCOPED_TRACE(engine);
    audit::AuditRequest a = request(engine, QueueOrder::Fifo, false);
    const AuditSetup setup = audit_setup(a);
    audit::EngineRequest r;
    r.theta = 33;
    r.timeout_seconds = 1e-6;
    const audit::EngineRun run = setup.engine(p, r);
    EXPECT_EQ(run.status, audit::RunStatus::TimedOut) << run.detail;
    EXPECT_NE(run.detail.find("time limit"), std::string::npos) << run.detail;
  }
}

// The default stays fifo, and says nothing of an order.
TEST(AuditOrder, FifoIsTheDefault) {
  const Pslg p = square400();
  audit::AuditRequest a;
  a.engine = "fast";
  a.no_isolate = true;
  a.compare = "none";
  a.root = LEPP_SOURCE_DIR;
  const AuditSetup setup = audit_setup(a);
  audit::EngineRequest r;
  r.theta = 30;
  r.timeout_seconds = 60;
  EXPECT_EQ(*setup.engine(p, r).trace, refine_trace(Engine::Fast, p, Method::Centroid, 30, QueueOrder::Fifo));
  EXPECT_EQ(setup.options.engine_name, "lepp fast");
  EXPECT_EQ(setup.options.reproduce_prefix.find("--order"), std::string::npos);
}

}  // namespace
}  // namespace lepp::engines
