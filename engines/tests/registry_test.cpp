// SPDX-License-Identifier: GPL-3.0-or-later
// The registry, looped over: every name parses back, every in-process engine refines.
#include <gtest/gtest.h>

#include <string>
#include <tuple>
#include <vector>

#include "lepp/engines/registry.h"
#include "lepp/io.h"
#include "lepp/validate.h"

namespace lepp::engines {
namespace {

TEST(EngineRegistry, EveryEngineNameParsesBack) {
  for (Engine e : all_engines()) {
    SCOPED_TRACE(to_string(e));
    EXPECT_EQ(parse_engine(to_string(e)), e);
  }
  EXPECT_EQ(parse_engine("Fast"), std::nullopt);
  EXPECT_EQ(parse_engine("triangle", lepp_engines()), std::nullopt);  // not among the choices
}

TEST(EngineRegistry, EveryMethodAndOrderNameParsesBack) {
  for (Method m : all_methods()) EXPECT_EQ(parse_method(to_string(m)), m) << to_string(m);
  for (QueueOrder o : all_queue_orders()) EXPECT_EQ(parse_order(to_string(o)), o) << to_string(o);
  EXPECT_EQ(parse_method("Centroid"), std::nullopt);
  EXPECT_EQ(parse_order("depth-first"), std::nullopt);
}

// The names as the commands' checks and messages have always listed them.
TEST(EngineRegistry, NamesKeepTheirOrder) {
  EXPECT_EQ(names(lepp_engines()), (std::vector<std::string>{"fast", "reference"}));
  EXPECT_EQ(names(audit_engines()), (std::vector<std::string>{"fast", "reference", "triangle", "cgal"}));
  EXPECT_EQ(names(comparison_engines()), (std::vector<std::string>{"reference", "fast", "triangle", "cgal"}));
  EXPECT_EQ(names(auto_comparisons()), (std::vector<std::string>{"reference", "triangle"}));
  EXPECT_EQ(method_names(), (std::vector<std::string>{"centroid", "midpoint"}));
  EXPECT_EQ(order_names(), (std::vector<std::string>{"fifo", "lifo", "flip", "random", "smallest-angle", "batch"}));
  EXPECT_EQ(order_names(audit_orders()), (std::vector<std::string>{"fifo", "lifo"}));
  EXPECT_EQ(quoted_choices(method_names()), "'centroid' or 'midpoint'");
  EXPECT_EQ(quoted_choices(order_names()), "'fifo', 'lifo', 'flip', 'random', 'smallest-angle' or 'batch'");
  EXPECT_EQ(quoted_choices(names(lepp_engines())), "'fast' or 'reference'");
}

TEST(EngineRegistry, AuditTitles) {
  EXPECT_EQ(audit_title(Engine::Fast), "lepp fast");
  EXPECT_EQ(audit_title(Engine::Reference, QueueOrder::Lifo), "lepp reference (lifo)");
  EXPECT_EQ(audit_title(Engine::Triangle, QueueOrder::Lifo), "Triangle (triangle-wasm)");
  EXPECT_EQ(audit_title(Engine::Cgal), "CGAL refine_Delaunay_mesh_2");
  EXPECT_EQ(comparison_title(Engine::Reference), "lepp reference");
  EXPECT_EQ(comparison_title(Engine::Triangle), "Triangle");
  EXPECT_EQ(comparison_title(Engine::Cgal), "CGAL");
  EXPECT_THROW(audit_title(Engine::Command), std::invalid_argument);
}

TEST(EngineRegistry, OnlyLeppsEnginesRunInProcess) {
  for (Engine e : all_engines()) {
    EXPECT_EQ(is_lepp_engine(e), e == Engine::Fast || e == Engine::Reference) << to_string(e);
    if (!is_lepp_engine(e)) {
      EXPECT_THROW(refine_function(e), std::invalid_argument) << to_string(e);
      EXPECT_THROW(build_cdt(e, Pslg{}), std::invalid_argument) << to_string(e);
    }
  }
}

Pslg paper_problem(const std::string& name) {
  std::vector<std::string> warnings;
  return validate(read_poly(std::string(LEPP_SOURCE_DIR) + "/corpus/paper/" + name + ".poly"), warnings);
}

// Every in-process engine, every method, every order: paper problem A refines to a
// converged mesh over the CDT the engine builds.
class LeppEngineRefines : public testing::TestWithParam<std::tuple<Engine, Method, QueueOrder>> {};

TEST_P(LeppEngineRefines, PaperProblemA) {
  const auto [engine, method, order] = GetParam();
  const Pslg p = paper_problem("A");
  const Mesh cdt = build_cdt(engine, p);
  EXPECT_FALSE(cdt.triangles.empty());
  EXPECT_EQ(cdt.vertices.size(), p.vertices.size());
  RefineOptions o;
  o.min_angle_deg = 25;
  o.method = method;
  o.order = order;
  o.order_seed = 1;
  o.threads = 1;
  const RefineResult r = refine(engine, p, o);
  EXPECT_EQ(r.outcome, Outcome::Converged);
  EXPECT_GT(r.steiner_points, 0);
  EXPECT_EQ(r.mesh.vertices.size(), p.vertices.size() + static_cast<std::size_t>(r.steiner_points));
  EXPECT_EQ(refine_function(engine)(p, o).mesh.vertices, r.mesh.vertices);  // the same engine either way
}

std::string case_name(const testing::TestParamInfo<LeppEngineRefines::ParamType>& info) {
  std::string name = std::string(to_string(std::get<0>(info.param))) + "_" + to_string(std::get<1>(info.param)) + "_" +
                     to_string(std::get<2>(info.param));
  for (char& c : name)
    if (c == '-') c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Registry, LeppEngineRefines,
                         testing::Combine(testing::ValuesIn(lepp_engines()), testing::ValuesIn(all_methods()),
                                          testing::ValuesIn(all_queue_orders())),
                         case_name);

}  // namespace
}  // namespace lepp::engines
