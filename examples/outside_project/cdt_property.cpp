// SPDX-License-Identifier: GPL-3.0-or-later
// One property, written the way another mesher's CI would: for every generated
// PSLG, the mesh under test (here lepp's reference CDT, by the engine registry; put yours instead)
// certifies exactly as a constrained Delaunay triangulation, Theorem 2 included.
#include <cstdio>
#include <vector>

#include <rapidcheck.h>

#include "lepp/certify.h"
#include "lepp/engines/registry.h"
#include "lepp/gen.h"
#include "lepp/validate.h"

int main() {
  const bool ok = rc::check("the CDT of any generated PSLG certifies", [] {
    std::vector<std::string> warnings;
    const lepp::Pslg pslg = lepp::validate(*lepp::gen::anyPslg(), warnings);
    RC_TAG(pslg.source);
    const lepp::Mesh mesh = lepp::engines::build_cdt(lepp::engines::Engine::Reference, pslg);
    const lepp::certify::Report report = lepp::certify::certify(pslg, mesh);
    if (!report.certified()) RC_FAIL(lepp::certify::format_report(report));
  });
  std::printf("%s\n", ok ? "property holds" : "property FAILED");
  return ok ? 0 : 1;
}
