// SPDX-License-Identifier: GPL-3.0-or-later
// inexact-threshold, inexact-incircle: the certifier's findings within double rounding.
#include "lepp/audit/judge/inexact.h"

#include <array>

#include <CGAL/Mpzf.h>

#include "lepp/angle.h"

namespace lepp::audit {
namespace {

using NT = CGAL::Mpzf;  // exact +, -, * of doubles

NT abs(const NT& x) { return x < 0 ? -x : x; }

NT len2(const Point& p, const Point& q) {
  const NT dx = NT(q.x) - NT(p.x), dy = NT(q.y) - NT(p.y);
  return dx * dx + dy * dy;
}

// The row's violations of every check it reads, counted (listed or not).
std::size_t counted(const certify::Report& report, std::initializer_list<certify::Check> checks) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < report.count_by_reason.size(); ++i)
    for (certify::Check ch : checks)
      if (certify::check_of(static_cast<certify::Reason>(i)) == ch) n += report.count_by_reason[i];
  return n;
}

// n when every violation of the checks is listed and passes `ok`; 0 otherwise,
// with *unlisted set when only the unlisted ones are unknown.
template <class Ok>
std::size_t all_of(const certify::Report& report, std::initializer_list<certify::Check> checks, bool* unlisted, Ok ok) {
  if (unlisted) *unlisted = false;
  const std::size_t total = counted(report, checks);
  std::size_t n = 0;
  for (const certify::Violation& v : report.violations) {
    bool mine = false;
    for (certify::Check ch : checks) mine = mine || certify::check_of(v.reason) == ch;
    if (!mine) continue;
    if (!ok(v)) return 0;
    ++n;
  }
  if (n == total) return n;
  if (unlisted) *unlisted = true;  // some not listed: undecided, so not named
  return 0;
}

}  // namespace

bool angle_within_rounding_below(const Point& a, const Point& b, const Point& c, double theta_deg) {
  // The vertex opposite a shortest edge has the smallest angle.
  const std::array<Point, 3> p = {a, b, c};
  std::array<NT, 3> opposite = {len2(b, c), len2(c, a), len2(a, b)};
  std::size_t o = 0;
  for (std::size_t k = 1; k < 3; ++k)
    if (opposite[k] < opposite[o]) o = k;
  const Point &v = p[o], &u1 = p[(o + 1) % 3], &u2 = p[(o + 2) % 3];
  const NT ux = NT(u1.x) - NT(v.x), uy = NT(u1.y) - NT(v.y), wx = NT(u2.x) - NT(v.x), wy = NT(u2.y) - NT(v.y);
  const NT cross = ux * wy - uy * wx;
  // sin^2 alpha = cross^2 / (|u|^2 |w|^2) > lo - bound, without dividing.
  const NT low = NT(sin2_bracket(theta_deg).lo) - NT(kThresholdRounding);
  return cross * cross > low * ((ux * ux + uy * uy) * (wx * wx + wy * wy));
}

bool incircle_within_rounding(const Point& a, const Point& b, const Point& c, const Point& d) {
  const NT adx = NT(a.x) - NT(d.x), ady = NT(a.y) - NT(d.y), bdx = NT(b.x) - NT(d.x), bdy = NT(b.y) - NT(d.y),
           cdx = NT(c.x) - NT(d.x), cdy = NT(c.y) - NT(d.y);
  const NT alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy, clift = cdx * cdx + cdy * cdy;
  const NT bc = bdx * cdy - cdx * bdy, ca = cdx * ady - adx * cdy, ab = adx * bdy - bdx * ady;
  const NT det = alift * bc + blift * ca + clift * ab;
  const NT permanent = (abs(bdx * cdy) + abs(cdx * bdy)) * alift + (abs(cdx * ady) + abs(adx * cdy)) * blift +
                       (abs(adx * bdy) + abs(bdx * ady)) * clift;
  return abs(det) <= NT(kIncircleRounding) * permanent;
}

std::size_t inexact_incircle_edges(const certify::Report& report, bool* unlisted) {
  return all_of(report, {certify::Check::Topology, certify::Check::InputVertices, certify::Check::Constraints,
                         certify::Check::Delaunay}, unlisted,
                [](const certify::Violation& v) {
                  // points: the edge's ends, the apex on its side, the opposite vertex (certify.cpp).
                  return v.reason == certify::Reason::NotLocallyDelaunay && v.points.size() == 4 &&
                         incircle_within_rounding(v.points[0], v.points[1], v.points[2], v.points[3]);
                });
}

std::size_t inexact_threshold_triangles(const certify::Report& report, double theta_deg, bool* unlisted) {
  return all_of(report, {certify::Check::MinAngle}, unlisted, [&](const certify::Violation& v) {
    return (v.reason == certify::Reason::AngleBelowTheta || v.reason == certify::Reason::AngleNotCertified) &&
           v.points.size() == 3 && angle_within_rounding_below(v.points[0], v.points[1], v.points[2], theta_deg);
  });
}

const char* inexact_definition(const std::string& name) {
  if (name == kInexactThreshold)
    return "a triangle treated as good or bad against theta where its smallest angle is within double rounding of theta "
           "(|sin^2 alpha - sin^2 theta| < 16 DBL_EPSILON, exactly): the threshold compared in double";
  if (name == kInexactIncircle)
    return "an edge not locally Delaunay whose quad is cocircular within double rounding (|incircle determinant| <= "
           "16 DBL_EPSILON times its permanent, exactly): a flip decided the other way by an in-circle test in double";
  return "";
}

}  // namespace lepp::audit
