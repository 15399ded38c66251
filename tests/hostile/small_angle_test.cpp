// SPDX-License-Identifier: GPL-3.0-or-later
// Small input angles (issue 7): on PSLGs with input angles down to 1 degree,
// refinement at theta <= 30 terminates on its own (converged or unimprovable,
// never a guard stop), and every triangle not listed unimprovable reaches theta
// (the certifier checks the angle of every other triangle and that each listed
// one satisfies ALGORITHM.md section 8). Both engines, fixed seed by default;
// RC_PARAMS overrides (RapidCheck prints the reproduce string on failure).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "hostile_support.h"
#include "lepp/certify.h"
#include "lepp/gen.h"
#include "lepp/io.h"
#include "lepp/validate.h"

namespace {
// Deterministic unless RC_PARAMS is set.
const int kRcDefaults = (setenv("RC_PARAMS", "seed=20261122 max_success=60", 0), 0);
}  // namespace

namespace lepp::hostile {
namespace {

// k cracks fanning out of one apex inside a box, consecutive ones `gaps[i]`
// degrees apart (1 to 10): many small input angles at one vertex, and between
// cracks of different lengths. Lattice points, so every predicate is exact.
rc::Gen<Pslg> crackFan() {
  return rc::gen::apply(
      [](std::vector<int> gaps, int radius, int start_deg) {
        Pslg p;
        p.source = "fan";
        const double box = 2.0 * radius;
        p.vertices = {{-box, -box}, {box, -box}, {box, box}, {-box, box}, {0, 0}};
        p.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
        double angle = start_deg;
        for (std::size_t k = 0; k <= gaps.size(); ++k) {
          if (k > 0) angle += gaps[k - 1];
          const double r = radius * (k % 2 ? 1.0 : 0.75);  // alternate lengths
          const double a = angle * M_PI / 180;
          p.vertices.push_back({std::round(r * std::cos(a)), std::round(r * std::sin(a))});
          p.segments.push_back({4, static_cast<int>(p.vertices.size() - 1)});
        }
        return p;
      },
      rc::gen::container<std::vector<int>>(*rc::gen::inRange(1, 5), rc::gen::inRange(1, 11)),
      rc::gen::inRange(128, 1025), rc::gen::inRange(0, 90));
}

std::string as_poly(const Pslg& p) {
  std::ostringstream s;
  s << p.vertices.size() << " 2 0 0\n";
  for (std::size_t i = 0; i < p.vertices.size(); ++i) s << i + 1 << " " << p.vertices[i].x << " " << p.vertices[i].y << "\n";
  s << p.segments.size() << " 0\n";
  for (std::size_t i = 0; i < p.segments.size(); ++i) s << i + 1 << " " << p.segments[i].a + 1 << " " << p.segments[i].b + 1 << "\n";
  s << "0\n";
  return s.str();
}

void terminates_and_reaches_theta(const Pslg& generated) {
  std::vector<std::string> warnings;
  Pslg p;
  try {
    p = validate(generated, warnings);
  } catch (const InputError& e) {
    RC_DISCARD(e.what());  // e.g. rounding made two cracks collinear and overlapping into a zero-length piece
  }
  RefineOptions o;
  o.min_angle_deg = *rc::gen::element(20.0, 25.0, 30.0);
  o.method = *rc::gen::element(Method::Centroid, Method::Midpoint);
  o.max_steiner = 50000;  // far above what these inputs need; hitting it means a cascade
  RC_TAG(generated.source, o.min_angle_deg, to_string(o.method));
  for (const EngineRun& run : run_engines(p, o)) {
    RC_TAG(run.engine, to_string(run.result.outcome));
    RC_LOG() << run.engine << ": " << to_string(run.result.outcome) << ", " << run.result.steiner_points
             << " Steiner points " << run.result.stuck << "\n" << as_poly(generated);
    RC_ASSERT(finished(run.result.outcome));
    certify::Options c;
    c.min_angle_deg = o.min_angle_deg;
    c.unimprovable = run.result.unimprovable;
    const certify::Report report = certify::certify(p, run.result.mesh, c);
    if (!report.certified()) RC_FAIL(run.engine + ": " + certify::format_report(report));
    RC_ASSERT(report.unimprovable_accepted.size() == run.result.unimprovable.size());
  }
}

RC_GTEST_PROP(SmallInputAngles, WedgesTerminateAndEveryUnlistedTriangleReachesTheta, ()) {
  terminates_and_reaches_theta(*gen::smallInputAngle());
}

RC_GTEST_PROP(SmallInputAngles, CrackFansTerminateAndEveryUnlistedTriangleReachesTheta, ()) {
  terminates_and_reaches_theta(*crackFan());
}

}  // namespace
}  // namespace lepp::hostile
