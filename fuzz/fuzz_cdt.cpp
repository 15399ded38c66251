// SPDX-License-Identifier: GPL-3.0-or-later
// fuzz_cdt: the fast engine's CDT build (lepp::fast::build_cdt) on point sets
// and segments, certified (no angle check), and compared with CGAL's CDT of the
// same input with the same domain rule (support/cgal_cdt.h): with no cocircular
// ties the triangles and the constrained edges must be the same.
#include <algorithm>
#include <cstdint>
#include <optional>

#include <fmt/format.h>

#include "lepp/engines/registry.h"
#include "lepp/io.h"
#include "support/certify_result.h"
#include "support/cgal_cdt.h"
#include "support/finding.h"
#include "support/fuzz_input.h"
#include "support/pslg_mutator.h"

using namespace lepp::fuzz;
using lepp::engines::Engine;

namespace {
void finding(const std::string& cls, const std::string& what) { report_finding("fuzz_cdt", cls, what); }

std::vector<std::pair<int, int>> edge_pairs(const lepp::Mesh& mesh) {
  std::vector<std::pair<int, int>> edges;
  for (const lepp::ConstrainedEdge& e : mesh.constrained_edges) edges.emplace_back(std::minmax(e.a, e.b));
  std::sort(edges.begin(), edges.end());
  return edges;
}

std::string first_difference(const lepp::Mesh& fast, const lepp::Mesh& cgal) {
  if (fast.triangles.size() != cgal.triangles.size())
    return fmt::format("{} triangles, CGAL {}", fast.triangles.size(), cgal.triangles.size());
  for (std::size_t i = 0; i < fast.triangles.size(); ++i)
    if (fast.triangles[i] != cgal.triangles[i])
      return fmt::format("triangle {}: ({} {} {}) vs CGAL ({} {} {})", i, fast.triangles[i][0], fast.triangles[i][1],
                         fast.triangles[i][2], cgal.triangles[i][0], cgal.triangles[i][1], cgal.triangles[i][2]);
  if (edge_pairs(fast) != edge_pairs(cgal)) return "constrained edges differ";
  return {};
}
}  // namespace

LEPP_FUZZ_PSLG_MUTATOR

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzInput input = decode(data, size);
  apply_environment(input);  // LEPP_FUZZ_PRECISION (method and theta do not matter here)
  const std::optional<lepp::Pslg> valid = valid_pslg(input);
  if (!valid) return 0;
  const lepp::Pslg& pslg = *valid;
  lepp::Mesh fast;
  try {
    fast = build_cdt(Engine::Fast, pslg);
  } catch (const std::exception& e) {
    finding("engine-exception", fmt::format("{}: {}", describe(input), e.what()));
    return 0;
  }
  if (std::string problems = certify_problems(pslg, fast, 0, {}); !problems.empty())
    finding("cdt-not-certified", fmt::format("{}: {}", describe(input), problems));
  const CgalCdt cgal = cgal_cdt(pslg);
  if (cgal.cocircular_edges > 0) return 0;  // the CDT is not unique
  lepp::canonicalize(fast);
  if (std::string diff = first_difference(fast, cgal.mesh); !diff.empty())
    finding("cdt-mismatch", fmt::format("{}: {}", describe(input), diff));
  return 0;
}
