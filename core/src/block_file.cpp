// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind block_file.h: an output file written in large blocks.
#include "block_file.h"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <system_error>
#include <vector>

#include <unistd.h>

namespace lepp::detail {
namespace {
[[noreturn]] void fail(const std::string& path, const char* what) {
  const int e = errno ? errno : EIO;
  throw std::system_error(e, std::generic_category(), fmt::format("{}: cannot {}", path, what));
}
}  // namespace

BlockFile::BlockFile(const std::string& path) : path_(path) {
  buffer_.reserve(kBlock + kSlack);
  errno = 0;
  file_ = std::fopen(path.c_str(), "wb");
  if (!file_) fail(path_, "open for writing");
}

BlockFile::~BlockFile() {
  if (file_) std::fclose(file_);
}

void BlockFile::bytes(const void* data, std::size_t n) {
  if (buffer_.size() + n > kBlock) flush();
  if (n >= kBlock) {  // a big array goes straight out
    errno = 0;
    if (std::fwrite(data, 1, n, file_) != n) fail(path_, "write");
    return;
  }
  const char* p = static_cast<const char*>(data);
  buffer_.append(p, p + n);
}

void BlockFile::flush() {
  if (buffer_.size() == 0) return;
  errno = 0;
  if (std::fwrite(buffer_.data(), 1, buffer_.size(), file_) != buffer_.size()) fail(path_, "write");
  buffer_.clear();
}

void BlockFile::copy_from(int fd, std::size_t n) {
  flush();
  errno = 0;
  if (std::fflush(file_) != 0) fail(path_, "write");
  const int out = ::fileno(file_);
  off_t at = 0;
  bool copied = false;  // past stdio, by the kernel
  while (n > 0) {
    const ssize_t c = ::copy_file_range(fd, &at, out, nullptr, n, 0);
    if (c < 0 && errno == EINTR) continue;
    if (c <= 0) break;  // not here (a pipe, a device, an old kernel): by hand below
    n -= static_cast<std::size_t>(c);
    copied = true;
  }
  std::vector<char> block(n > 0 ? kBlock : 0);
  while (n > 0) {
    const ssize_t r = ::pread(fd, block.data(), std::min(n, kBlock), at);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) fail(path_, "copy the lines made beside the refinement into");
    if (std::fwrite(block.data(), 1, static_cast<std::size_t>(r), file_) != static_cast<std::size_t>(r)) fail(path_, "write");
    at += r;
    n -= static_cast<std::size_t>(r);
  }
  // The stream's position after the bytes the kernel wrote past it (a regular file:
  // copy_file_range writes nothing else).
  if (copied && std::fseek(file_, 0, SEEK_END) != 0) fail(path_, "write");
}

void BlockFile::close() {
  flush();
  std::FILE* f = file_;
  file_ = nullptr;
  errno = 0;
  if (std::fclose(f) != 0) fail(path_, "write");
}

bool little_endian() {
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

}  // namespace lepp::detail
