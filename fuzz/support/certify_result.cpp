// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind certify_result.h: the certifier as the fuzz targets use it.
#include "certify_result.h"

#include <algorithm>
#include <cstdlib>
#include <set>
#include <string>

#include <fmt/format.h>

#ifdef LEPP_FUZZ_HAVE_CERTIFIER
#include "lepp/certify.h"
#endif

namespace lepp::fuzz {
#ifdef LEPP_FUZZ_HAVE_CERTIFIER
namespace {

Tri sorted_ids(Tri t) {
  std::sort(t.begin(), t.end());
  return t;
}

}  // namespace
#endif

bool have_certifier() {
#ifdef LEPP_FUZZ_HAVE_CERTIFIER
  return true;
#else
  return false;
#endif
}

std::string certify_problems(const Pslg& pslg, const Mesh& mesh, double theta_deg,
                             const std::vector<UnimprovableTriangle>& unimprovable, Method method) {
  // Structural checks that need no exact arithmetic.
  const int n = static_cast<int>(mesh.vertices.size());
  for (const Tri& t : mesh.triangles)
    for (int v : t)
      if (v < 0 || v >= n) return fmt::format("triangle vertex id {} out of range [0, {})", v, n);
  if (mesh.input_vertices != pslg.vertices.size())
    return fmt::format("mesh has {} input vertices, the PSLG {}", mesh.input_vertices, pslg.vertices.size());
  for (std::size_t i = 0; i < pslg.vertices.size() && i < mesh.vertices.size(); ++i)
    if (mesh.vertices[i] != pslg.vertices[i]) return fmt::format("input vertex {} moved", i);
#ifdef LEPP_FUZZ_HAVE_CERTIFIER
  certify::Options options;
  options.min_angle_deg = theta_deg;
  options.unimprovable = unimprovable;
  options.precision_method = method;  // triangles listed at double precision are held to this method's choices
  options.max_listed_per_reason = 3;
  // LEPP_FUZZ_TIES_BY_IDS=1: precision leftovers are judged with lepp's own tie rule (equal lengths by
  // vertex ids; docs/CERTIFIER.md section 5c), so a campaign goes past that known limitation.
  const char* ties = std::getenv("LEPP_FUZZ_TIES_BY_IDS");
  options.precision_ties_by_ids = ties != nullptr && std::string(ties) == "1";
  const certify::Report report = certify::certify(pslg, mesh, options);
  if (!report.certified()) {
    std::size_t violations = 0;
    for (std::size_t c : report.count_by_reason) violations += c;
    // The tie search's bound: a claim undecided at it, or rejected on a triangle the
    // engine left with its own search cut at it (docs/THEOREMS.md, "Where the claim fails").
    std::set<Tri> cut;
    for (const UnimprovableTriangle& u : unimprovable)
      if (u.search_cut) cut.insert(sorted_ids(u.triangle));
    std::size_t at_bound = report.precision_undecided;
    for (const certify::PrecisionClaim& c : report.precision_claims)
      if (c.outcome == certify::PrecisionOutcome::Rejected && c.triangle >= 0 &&
          static_cast<std::size_t>(c.triangle) < mesh.triangles.size() &&
          cut.count(sorted_ids(mesh.triangles[static_cast<std::size_t>(c.triangle)])) > 0)
        ++at_bound;
    std::string text = violations == at_bound ? std::string(kPrecisionUndecided) : std::string();
    for (std::size_t i = 0; i < report.violations.size() && i < 3; ++i)
      text += fmt::format("[{}] {}; ", certify::to_string(report.violations[i].reason), report.violations[i].message);
    return text.empty() ? "not certified" : text;
  }
#else
  (void)theta_deg;
  (void)unimprovable;
  (void)method;
#endif
  return {};
}

std::string certify_result(const Pslg& pslg, const RefineOptions& options, const RefineResult& result) {
  const bool converged = result.outcome == Outcome::Converged || result.outcome == Outcome::Unimprovable;
  return certify_problems(pslg, result.mesh, converged ? options.min_angle_deg : 0, result.unimprovable,
                          options.method);
}

}  // namespace lepp::fuzz
