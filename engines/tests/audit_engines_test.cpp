// SPDX-License-Identifier: GPL-3.0-or-later
// lepp's engines as audit engines, looped over the registry: each runs a paper problem.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lepp/engines/builtin_engines.h"
#include "lepp/io.h"
#include "lepp/validate.h"

namespace lepp::engines {
namespace {

class LeppAuditEngine : public testing::TestWithParam<Engine> {};

TEST_P(LeppAuditEngine, RunsPaperProblemAWithItsTrace) {
  std::vector<std::string> warnings;
  const Pslg p = validate(read_poly(std::string(LEPP_SOURCE_DIR) + "/corpus/paper/A.poly"), warnings);
  for (Method method : all_methods()) {
    SCOPED_TRACE(to_string(method));
    audit::EngineRequest request;
    request.method = method;
    request.theta = 25;
    const audit::EngineRun run = lepp_audit_engine(GetParam())(p, request);
    EXPECT_EQ(run.status, audit::RunStatus::Ok) << run.detail;
    ASSERT_TRUE(run.trace.has_value());
    EXPECT_EQ(run.mesh.vertices.size(), p.vertices.size() + run.trace->size());
    // The registry's engine is the one the refine functions run.
    RefineOptions o;
    o.min_angle_deg = 25;
    o.method = method;
    EXPECT_EQ(refine(GetParam(), p, o).mesh.vertices, run.mesh.vertices);
  }
}

INSTANTIATE_TEST_SUITE_P(Registry, LeppAuditEngine, testing::ValuesIn(lepp_engines()),
                         [](const testing::TestParamInfo<Engine>& info) { return std::string(to_string(info.param)); });

}  // namespace
}  // namespace lepp::engines
