// SPDX-License-Identifier: GPL-3.0-or-later
// An output file written in large blocks: text (fmt) and raw bytes are
// gathered in memory and written 1 MiB at a time, so the writers of big meshes
// make a few thousand system calls, not one per element. Internal to lepp_core.
#pragma once
#include <cstdio>
#include <iterator>
#include <string>
#include <type_traits>

#include <fmt/compile.h>
#include <fmt/format.h>

namespace lepp::detail {

class BlockFile {
 public:
  // Throws std::system_error naming the path when it cannot be opened.
  explicit BlockFile(const std::string& path);
  BlockFile(const BlockFile&) = delete;
  BlockFile& operator=(const BlockFile&) = delete;
  ~BlockFile();  // closes (errors ignored) if close() was not called

  template <class... Args>
  void print(fmt::format_string<Args...> format, Args&&... args) {
    fmt::format_to(fmt::appender(buffer_), format, std::forward<Args>(args)...);
    if (buffer_.size() >= kBlock) flush();
  }
  // The same with a format of FMT_COMPILE, turned into code by the compiler instead
  // of parsed at every call: for the lines written once per vertex or element.
  template <class Compiled, class... Args,
            std::enable_if_t<fmt::detail::is_compiled_string<Compiled>::value, int> = 0>
  void print(const Compiled& format, Args&&... args) {
    fmt::format_to(fmt::appender(buffer_), format, std::forward<Args>(args)...);
    if (buffer_.size() >= kBlock) flush();
  }
  // A line of at most `room` bytes written by write(char* at) straight into the
  // buffer (it returns the end): fmt::format_to into a plain pointer formats a
  // double without copying its digits through the buffer's output iterator (the
  // .node's coordinates; issue 40).
  template <class Write>
  void line(std::size_t room, Write&& write) {
    const std::size_t at = buffer_.size();
    buffer_.resize(at + room);  // within the capacity made at once
    char* const end = write(buffer_.data() + at);
    buffer_.resize(static_cast<std::size_t>(end - buffer_.data()));
    if (buffer_.size() >= kBlock) flush();
  }
  void bytes(const void* data, std::size_t n);
  // One value's bytes, in this machine's byte order (the formats say which).
  template <class T>
  void raw(const T& value) {
    bytes(&value, sizeof value);
  }
  // Appends `n` bytes of file `fd` from its offset 0 (the .node's lines made beside
  // the refinement, node_text_stream.h): copied in the kernel where it can
  // (copy_file_range), else read and written. Throws std::system_error naming this
  // file's path on a failed write.
  void copy_from(int fd, std::size_t n);
  // Writes what is left and closes; throws std::system_error on any failure
  // (a full disk shows here).
  void close();

 private:
  // 1 MiB: the block stays in cache until it is written, and its buffer is made
  // at its full size at once (kSlack for the line that crosses the mark): grown
  // from fmt's 500 bytes by halves, it touched about three times its size in fresh
  // pages, page faults that were 15 % of those of a 10^6-triangle refinement.
  static constexpr std::size_t kBlock = std::size_t{1} << 20;
  static constexpr std::size_t kSlack = std::size_t{1} << 16;
  void flush();
  std::string path_;
  std::FILE* file_ = nullptr;
  fmt::memory_buffer buffer_;
};

// True on a little-endian machine (for the .vtu's byte_order).
bool little_endian();

}  // namespace lepp::detail
