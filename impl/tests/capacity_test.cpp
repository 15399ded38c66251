// SPDX-License-Identifier: GPL-3.0-or-later
// The fast engine's id capacity (capacity.h): the largest ids survive the packed
// words, the next would alias, and the refinement stops with CapacityError before
// any id passes the limit, reached here on a small mesh with lowered limits.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "capacity.h"
#include "lepp/fast.h"
#include "lepp/io.h"
#include "lepp/validate.h"
#include "tri_mesh.h"

namespace lepp::fast {
namespace {

constexpr std::int64_t kTwo29 = std::int64_t{1} << 29;

TEST(Capacity, IdsFitUpToTwoToThe29OfEach) {
  EXPECT_TRUE(ids_fit(kTwo29 - 1, kTwo29 - 1));
  EXPECT_TRUE(ids_fit(kTwo29, kTwo29));  // ids 0 .. 2^29 - 1
  EXPECT_FALSE(ids_fit(kTwo29 + 1, 3));
  EXPECT_FALSE(ids_fit(3, kTwo29 + 1));
  EXPECT_FALSE(ids_fit(kTwo29 + 1, kTwo29 + 1));
}

// The limits are the packing's: the largest id reads back with every flag set,
// and the next one does not (why the guard stands where it does).
TEST(Capacity, TheLargestIdsRoundTripAndTheNextWouldAlias) {
  const int last = static_cast<int>(kMaxVertices - 1);
  const FTri f({last, last - 1, 0}, {-1, -1, -1}, {0, 0, -1}, 2);
  EXPECT_EQ(f.v(0), last);
  EXPECT_EQ(f.v(1), last - 1);
  EXPECT_EQ(f.seg(0), 0);
  EXPECT_EQ(f.seg(1), 0);
  EXPECT_EQ(f.seg(2), -1);
  EXPECT_EQ(f.longest(), 2);
  const FTri past({last + 1, 1, 2}, {-1, -1, -1}, {-1, -1, -1}, -1);
  EXPECT_NE(past.v(0), last + 1);  // 2^29 would alias a smaller id (and set a flag)

  const int last_tri = static_cast<int>(kMaxTriangles - 1);
  const int code = nbr_code(last_tri, 2);
  EXPECT_GE(code, 0);
  EXPECT_EQ(nbr_tri(code), last_tri);
  EXPECT_EQ(nbr_edge(code), 2);
}

TEST(Capacity, CheckThrowsCapacityErrorNamingTheCountsAndTheBudget) {
  EXPECT_NO_THROW(check_capacity(kTwo29, kTwo29, 0));
  try {
    check_capacity(kTwo29, kTwo29 + 1, 268435000);
    FAIL() << "no CapacityError";
  } catch (const CapacityError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("536870913 triangles"), std::string::npos) << what;
    EXPECT_NE(what.find("at most 536870912 vertices and 536870912 triangles"), std::string::npos) << what;
    EXPECT_NE(what.find("--max-steiner 268435000"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << "one line";
  }
  EXPECT_THROW(check_capacity(kTwo29 + 1, 4, 0), CapacityError);
  try {
    check_capacity(kTwo29 / 2 + 1, kTwo29 + 2, kInputOnly);
    FAIL() << "no CapacityError";
  } catch (const CapacityError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("the input outgrows"), std::string::npos) << what;
    EXPECT_EQ(what.find("--max-steiner"), std::string::npos) << "no budget helps an input: " << what;
  }
}

// Lowered limits for one test, restored after it.
class Limits {
 public:
  Limits(std::int64_t vertices, std::int64_t triangles) : saved_(id_limits()) { id_limits() = {vertices, triangles}; }
  ~Limits() { id_limits() = saved_; }
  Limits(const Limits&) = delete;
  Limits& operator=(const Limits&) = delete;

 private:
  IdLimits saved_;
};

// Square400 fills its convex hull, so every triangle slot is a triangle of the mesh:
// limits at the final mesh's counts let it converge, one less stops the run.
TEST(Capacity, RefinementStopsBeforeTheLimitAndNotAtIt) {
  std::vector<std::string> warnings;
  const Pslg p = validate(read_poly(std::string(LEPP_SOURCE_DIR) + "/corpus/paper/square400.poly"), warnings);
  RefineOptions o;
  o.min_angle_deg = 25;
  const RefineResult full = refine(p, o);
  ASSERT_EQ(full.outcome, Outcome::Converged);
  const auto v = static_cast<std::int64_t>(full.mesh.vertices.size());
  const auto t = static_cast<std::int64_t>(full.mesh.triangles.size());
  {
    Limits at(v, t);
    const RefineResult again = refine(p, o);
    EXPECT_EQ(again.outcome, Outcome::Converged);
    EXPECT_EQ(again.mesh.triangles, full.mesh.triangles);
  }
  {
    Limits below(v - 1, t);
    EXPECT_THROW(refine(p, o), CapacityError);
  }
  {
    Limits below(v, t - 1);
    EXPECT_THROW(refine(p, o), CapacityError);
  }
  // An input past the limit, or whose triangulation could be (2 n triangles): refused
  // before the initial triangulation.
  const auto n = static_cast<std::int64_t>(p.vertices.size());
  for (const IdLimits limits : {IdLimits{n - 1, t}, IdLimits{n, 2 * n - 1}}) {
    Limits input(limits.vertices, limits.triangles);
    try {
      refine(p, o);
      ADD_FAILURE() << "no CapacityError at limits " << limits.vertices << ", " << limits.triangles;
    } catch (const CapacityError& e) {
      EXPECT_NE(std::string(e.what()).find("the input outgrows"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace lepp::fast
