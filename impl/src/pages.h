// SPDX-License-Identifier: GPL-3.0-or-later
// The fast engine's memory by whole pages (issue 40): rounding a byte range to the
// pages it covers, and the three calls the engine makes on them (give back, move,
// make resident). Elsewhere than on Linux, or on a kernel without the call, each
// does nothing and says so: the memory then behaves as the allocator gave it.
#pragma once
#include <cstdint>

namespace lepp::fast {

// The system's page size in bytes.
std::uintptr_t page_size();

// The whole pages within [begin, end), as addresses (to >= from).
struct Pages {
  std::uintptr_t from = 0, to = 0;
};
Pages pages_within(std::uintptr_t begin, std::uintptr_t end);
inline Pages pages_within(const unsigned char* begin, const unsigned char* end) {
  return pages_within(reinterpret_cast<std::uintptr_t>(begin), reinterpret_cast<std::uintptr_t>(end));
}

// Returns the whole pages within [begin, end) to the system: their contents are no
// longer needed.
void release_pages(unsigned char* begin, unsigned char* end);

// Moves the pages of [from, from_end), whose contents are no longer needed, to back
// the untouched storage [to, to_end), as far as whole pages of both go. Both must
// be private anonymous memory (the allocator's): the source stays mapped, empty
// (MREMAP_DONTUNMAP: zero pages on demand), so the memory already held is reused
// where fresh pages would each fault (about 2 us a page on the machines measured).
// False where nothing was moved (a kernel before 5.13): the caller releases the
// source instead.
bool move_pages(unsigned char* from, unsigned char* from_end, unsigned char* to, unsigned char* to_end);

// Makes the pages p resident and writable in one call (MADV_POPULATE_WRITE), their
// contents untouched. False when the system cannot (a kernel before 5.14).
bool populate_pages(Pages p);

}  // namespace lepp::fast
