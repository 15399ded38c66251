// SPDX-License-Identifier: GPL-3.0-or-later
// PopulateAhead (populate_ahead.h): an array past kLead bytes gets its next pages
// resident ahead of its end, here and on a second thread; a small one and the last
// stretch of a capacity are left alone; a reallocated array is followed to its new
// buffer. Residency is read with mincore; on a system that cannot populate (not
// Linux, a kernel before 5.14) the tests are skipped.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#ifdef __linux__
#include <sys/mman.h>
#include <unistd.h>
#endif

#include "populate_ahead.h"
#include "tri_mesh.h"

namespace lepp::fast {
namespace {

#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
std::uintptr_t page() { return static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE)); }

bool can_populate() {
  void* p = mmap(nullptr, page(), PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  const bool ok = p != MAP_FAILED && madvise(p, page(), MADV_POPULATE_WRITE) == 0;
  if (p != MAP_FAILED) munmap(p, page());
  return ok;
}

// How many of the whole pages in [from, to) are resident.
std::size_t resident_pages(const void* from, const void* to) {
  const std::uintptr_t a = (reinterpret_cast<std::uintptr_t>(from) + page() - 1) & ~(page() - 1);
  const std::uintptr_t b = reinterpret_cast<std::uintptr_t>(to) & ~(page() - 1);
  if (b <= a) return 0;
  std::vector<unsigned char> in((b - a) / page());
  EXPECT_EQ(mincore(reinterpret_cast<void*>(a), b - a, in.data()), 0);
  std::size_t n = 0;
  for (unsigned char c : in) n += c & 1;
  return n;
}
std::size_t pages_in(std::size_t bytes) { return bytes / page(); }

// A mesh whose arrays are reserved past 32 MiB each (glibc maps such blocks afresh:
// nothing in them is resident before it is written) and hold `slots` triangles,
// `slots / 2` points.
TriMesh grown_mesh(std::size_t slots, std::size_t capacity = std::size_t{1} << 23) {
  TriMesh m;
  m.reserve(capacity, capacity);
  m.grow(slots);
  for (std::size_t i = 0; i < slots / 2; ++i) m.pts.push_back({0, 0});
  return m;
}

// The lead's resident pages past the end of the triangles.
std::size_t resident_ahead(const TriMesh& m, std::size_t bytes) {
  const unsigned char* end = reinterpret_cast<const unsigned char*>(m.tris.data() + m.tris.size());
  return resident_pages(end + page(), end + bytes);
}

TEST(PopulateAhead, TheLeadIsResidentOnOneThreadAndOnTwo) {
  if (!can_populate()) GTEST_SKIP() << "this system cannot populate pages";
  for (bool beside : {false, true}) {
    TriMesh m = grown_mesh(PopulateAhead::kLead / sizeof(FTri) + 1);
    ASSERT_EQ(resident_ahead(m, PopulateAhead::kLead / 2), 0u) << beside;
    PopulateAhead ahead(beside);
    ahead.advance(m);
    ahead.wait();
    const std::size_t lead_pages = pages_in(PopulateAhead::kLead) - 3;  // whole pages of an unaligned range
    EXPECT_GE(resident_ahead(m, PopulateAhead::kLead - page()), lead_pages) << beside;
    // Not past the lead.
    const unsigned char* end = reinterpret_cast<const unsigned char*>(m.tris.data() + m.tris.size());
    EXPECT_EQ(resident_pages(end + PopulateAhead::kLead + page(), end + 4 * PopulateAhead::kLead), 0u) << beside;
    // The points and stamps too, each its own lead.
    const unsigned char* pts_end = reinterpret_cast<const unsigned char*>(m.pts.data() + m.pts.size());
    if (m.pts.size() * sizeof(Point) >= PopulateAhead::kLead)
      EXPECT_GE(resident_pages(pts_end + page(), pts_end + PopulateAhead::kLead - page()), lead_pages - 2) << beside;
    // Half the lead used: populated again to a full lead past the new end.
    m.grow(PopulateAhead::kLead / 2 / sizeof(FTri) + 16);
    ahead.advance(m);
    ahead.wait();
    EXPECT_GE(resident_ahead(m, PopulateAhead::kLead - page()), lead_pages) << beside;
  }
}

TEST(PopulateAhead, ASmallArrayTakesItsFaults) {
  if (!can_populate()) GTEST_SKIP() << "this system cannot populate pages";
  TriMesh m = grown_mesh(PopulateAhead::kLead / sizeof(FTri) - 64);  // just below kLead bytes
  PopulateAhead ahead(false);
  ahead.advance(m);
  EXPECT_EQ(resident_ahead(m, PopulateAhead::kLead), 0u);
}

// Within two calls' growth of its capacity an array is left alone; once it moves to
// a larger buffer it is populated there.
TEST(PopulateAhead, NearItsCapacityAnArrayIsLeftThenFollowed) {
  if (!can_populate()) GTEST_SKIP() << "this system cannot populate pages";
  for (bool beside : {false, true}) {
    const std::size_t capacity = (std::size_t{40} << 20) / sizeof(FTri);  // 40 MiB of triangles
    const std::size_t growth = 2 * static_cast<std::size_t>(PopulateAhead::kEvery);
    TriMesh m = grown_mesh(capacity - 2 * growth + 1, capacity);
    PopulateAhead ahead(beside);
    ahead.advance(m);
    ahead.wait();
    EXPECT_EQ(resident_ahead(m, (2 * growth - 1) * sizeof(FTri)), 0u) << beside;
    // Grown past its capacity: a new buffer, resident up to the old size (the copy), then its lead.
    const FTri* old = m.tris.data();
    m.grow(2 * growth);
    ASSERT_NE(m.tris.data(), old);
    ahead.advance(m);
    ahead.wait();
    EXPECT_GE(resident_ahead(m, PopulateAhead::kLead - page()), pages_in(PopulateAhead::kLead) - 3) << beside;
  }
}
#else
TEST(PopulateAhead, NotOnThisSystem) { GTEST_SKIP() << "madvise(MADV_POPULATE_WRITE) is Linux's"; }
#endif

}  // namespace
}  // namespace lepp::fast
