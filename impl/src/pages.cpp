// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind pages.h.
#include "pages.h"

#include <algorithm>

#ifdef __linux__
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace lepp::fast {

std::uintptr_t page_size() {
#ifdef __linux__
  static const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
  return page;
#else
  return 4096;
#endif
}

Pages pages_within(std::uintptr_t begin, std::uintptr_t end) {
  const std::uintptr_t page = page_size();
  const std::uintptr_t from = (begin + page - 1) & ~(page - 1);
  const std::uintptr_t to = end & ~(page - 1);
  return {from, std::max(from, to)};
}

void release_pages(unsigned char* begin, unsigned char* end) {
#ifdef __linux__
  const Pages p = pages_within(begin, end);
  if (p.to > p.from) madvise(reinterpret_cast<void*>(p.from), p.to - p.from, MADV_DONTNEED);
#else
  (void)begin;
  (void)end;
#endif
}

bool move_pages(unsigned char* from, unsigned char* from_end, unsigned char* to, unsigned char* to_end) {
#if defined(__linux__) && defined(MREMAP_DONTUNMAP)
  const Pages source = pages_within(from, from_end), target = pages_within(to, to_end);
  const std::uintptr_t n = std::min(source.to - source.from, target.to - target.from);
  if (n == 0) return false;
  void* const moved = mremap(reinterpret_cast<void*>(source.from), n, n, MREMAP_MAYMOVE | MREMAP_FIXED | MREMAP_DONTUNMAP,
                             reinterpret_cast<void*>(target.from));
  if (moved == MAP_FAILED) return false;
  release_pages(reinterpret_cast<unsigned char*>(source.from + n), from_end);  // a page the target had no room for
  return true;
#else
  (void)from;
  (void)from_end;
  (void)to;
  (void)to_end;
  return false;
#endif
}

bool populate_pages(Pages p) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
  return madvise(reinterpret_cast<void*>(p.from), p.to - p.from, MADV_POPULATE_WRITE) == 0;
#else
  (void)p;
  return false;
#endif
}

}  // namespace lepp::fast
