// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind hostile_support.h: shared by the hostile-input tests.
#include "hostile_support.h"

#include <gtest/gtest.h>

#include "lepp/engines/registry.h"
#ifdef LEPP_HAVE_CERTIFY
#include "lepp/certify.h"
#endif

namespace lepp::hostile {

bool finished(Outcome outcome) { return outcome == Outcome::Converged || outcome == Outcome::Unimprovable; }

std::vector<EngineRun> run_engines(const Pslg& validated, const RefineOptions& options, bool reference) {
  std::vector<EngineRun> runs;
  for (engines::Engine e : engines::lepp_engines())
    if (reference || e != engines::Engine::Reference) runs.push_back({engines::to_string(e), engines::refine(e, validated, options)});
  return runs;
}

void expect_certified(const Pslg& validated, const EngineRun& run, double theta, const std::string& what) {
  // Always: a non-empty mesh whose ids are in range and whose first vertices are the input's.
  const Mesh& mesh = run.result.mesh;
  EXPECT_FALSE(mesh.triangles.empty()) << what << " (" << run.engine << ")";
  EXPECT_EQ(mesh.input_vertices, validated.vertices.size()) << what;
  for (std::size_t i = 0; i < validated.vertices.size() && i < mesh.vertices.size(); ++i)
    ASSERT_EQ(mesh.vertices[i], validated.vertices[i]) << what << ": input vertex " << i << " moved";
  for (const Tri& t : mesh.triangles)
    for (int v : t) ASSERT_TRUE(v >= 0 && static_cast<std::size_t>(v) < mesh.vertices.size()) << what;
#ifdef LEPP_HAVE_CERTIFY
  certify::Options options;
  options.min_angle_deg = finished(run.result.outcome) ? theta : 0;
  options.unimprovable = run.result.unimprovable;
  certify::Report report = certify::certify(validated, run.result.mesh, options);
  EXPECT_TRUE(report.certified()) << what << " (" << run.engine << ", outcome " << to_string(run.result.outcome)
                                  << "):\n" << certify::format_report(report);
#else
  (void)validated, (void)run, (void)theta, (void)what;
#endif
}

}  // namespace lepp::hostile
