// SPDX-License-Identifier: GPL-3.0-or-later
// Triangle (triangle-wasm under node, tools/triangle/triangle.js) on generated inputs
// with a small angle (gen:wedge, gen:wedge-cracks: 1 to 59 degrees) at 20, 25, 30
// degrees: every mesh certifies with the small-input-angle rule. Certified at
// theta - 1e-6 degrees: Triangle's own angle test rounds, and it leaves triangles a
// few ulps below theta (a finding kept in certify_exemption_test.cpp,
// TriangleRoundsItsAngleTest). Skipped, saying so, without triangle-wasm.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "lepp/certify.h"
#include "lepp/gen.h"
#include "lepp/io.h"
#include "lepp/validate.h"

namespace lepp {
namespace {

namespace fs = std::filesystem;

TEST(SmallAngleExemption, TriangleMeshesOfSmallAngleInputsCertifyWithTheRule) {
  if (!fs::exists(LEPP_SOURCE_DIR "/tools/triangle/node_modules/triangle-wasm"))
    GTEST_SKIP() << "SKIPPED: tools/triangle/node_modules/triangle-wasm is absent (run `npm ci` in tools/triangle)";
  const std::string node = LEPP_NODE_EXECUTABLE;
  ASSERT_FALSE(node.empty() || node.find("NOTFOUND") != std::string::npos) << "node is missing but triangle-wasm is installed";
  const fs::path dir = fs::temp_directory_path() / ("lepp_exempt_triangle_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const bool ok = rc::check("Triangle's meshes of small-angle inputs certify with the rule", [&] {
    std::vector<std::string> warnings;
    const Pslg p = validate(*gen::smallInputAngle(), warnings);
    const int theta = *rc::gen::element(20, 25, 30);
    const std::string prefix = (dir / "t").string();
    write_poly(prefix + ".in.poly", p);
    const std::string cmd = "\"" + node + "\" \"" LEPP_SOURCE_DIR "/tools/triangle/triangle.js\" \"" + prefix + ".in.poly\" -pq" +
                            std::to_string(theta) + " \"" + prefix + "\" > /dev/null 2>&1";
    RC_ASSERT(std::system(cmd.c_str()) == 0);
    const Mesh m = read_mesh(prefix);
    RC_TAG(p.source, theta);
    certify::Options c;
    c.min_angle_deg = theta - 1e-6;
    c.exempt_small_input_angles = true;
    const certify::Report report = certify::certify(p, m, c);
    if (!report.certified()) RC_FAIL("Triangle -pq" + std::to_string(theta) + ":\n" + certify::format_report(report));
  });
  fs::remove_all(dir);
  EXPECT_TRUE(ok);
}

}  // namespace
}  // namespace lepp
