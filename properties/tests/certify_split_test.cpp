// SPDX-License-Identifier: GPL-3.0-or-later
// The certifier and --split-crossings (issue 12): a crossing point is accepted
// where lepp rounds it and where another mesher rounds it an ulp away, and
// rejected one tolerance further off its segment.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cgal_mesh.h"
#include "lepp/certify.h"
#include "lepp/input.h"
#include "lepp/io.h"
#include "test_pslgs.h"

namespace lepp {
namespace {

Pslg crossing_pslg() { return test::crossing_split(LEPP_SOURCE_DIR); }
using test::as_read;

TEST(CertifySplitCrossings, RoundedCrossingPointsCertify) {
  const Pslg p = crossing_pslg();
  ASSERT_EQ(p.crossing_vertices, 8u);
  const certify::Report r = certify::certify(p, as_read(test::cgal_cdt(p)), {});
  EXPECT_TRUE(r.certified()) << certify::format_report(r);
}

TEST(CertifySplitCrossings, AnotherMeshersRoundingOneUlpAwayCertifies) {
  const Pslg p = crossing_pslg();
  Mesh m = as_read(test::cgal_cdt(p));
  const std::size_t x = p.vertices.size() - 1;  // a crossing point
  m.vertices[x].x = std::nextafter(m.vertices[x].x, HUGE_VAL);
  const certify::Report r = certify::certify(p, m, {});
  EXPECT_TRUE(r.certified()) << certify::format_report(r);
}

TEST(CertifySplitCrossings, OneToleranceFurtherOffIsRejected) {
  const Pslg p = crossing_pslg();
  const std::size_t x = p.vertices.size() - 1;
  // The file segment through x: the pieces of its origin group, ends A and B.
  std::size_t k = 0;
  while (p.segments[k].b != static_cast<int>(x)) ++k;
  std::size_t first = k, last = k;
  while (first > 0 && p.segment_origin[first - 1] == p.segment_origin[k]) --first;
  while (last + 1 < p.segments.size() && p.segment_origin[last + 1] == p.segment_origin[k]) ++last;
  const Point a = p.vertices[static_cast<std::size_t>(p.segments[first].a)];
  const Point b = p.vertices[static_cast<std::size_t>(p.segments[last].b)];
  const double tol = certify::segment_tolerance(a, b, last - first);
  // Move x along the segment's normal by the tolerance bound (in the
  // certifier's measure |cross| <= tol (|dx| + |dy|)) plus one tolerance.
  const double dx = b.x - a.x, dy = b.y - a.y, l2 = std::hypot(dx, dy), l1 = std::abs(dx) + std::abs(dy);
  const double t = tol * l1 / l2 + tol;
  Mesh m = as_read(test::cgal_cdt(p));
  m.vertices[x].x -= t * dy / l2;
  m.vertices[x].y += t * dx / l2;
  const certify::Report r = certify::certify(p, m, {});
  EXPECT_FALSE(r.certified());
  EXPECT_TRUE(r.has(certify::Reason::SteinerOffSegment)) << certify::format_report(r);
  // Where lepp put it, the same mesh certifies: the rejection is the move's doing.
  EXPECT_TRUE(certify::certify(p, as_read(test::cgal_cdt(p)), {}).certified());
}

}  // namespace
}  // namespace lepp
