// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind block_file.h: an output file written in large blocks.
#include "block_file.h"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <system_error>

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
