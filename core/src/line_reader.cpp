// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind line_reader.h: splits a Triangle-format text file into lines of
// whitespace-separated tokens, dropping comments (# to end of line) and blank lines, and
// converts tokens to numbers with errors that name the file and line.
#include "line_reader.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <vector>

#include <fmt/format.h>

#include "lepp/io.h"

namespace lepp::detail {
namespace {

// A token as it may appear in a one-line message: control bytes (NUL, ...)
// shown as \xNN, and at most 40 characters.
std::string printable(std::string_view token) {
  std::string out;
  for (char c : token.substr(0, 40)) {
    unsigned char u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f)
      out += fmt::format("\\x{:02x}", u);
    else
      out += c;
  }
  if (token.size() > 40) out += "...";
  return out;
}

// isspace() in the C locale, inline: the reader's innermost test (the library call was a
// tenth of reading a mesh). Bytes of 0x80 and above are not space, as in C and UTF-8 locales.
constexpr bool is_space(char c) { return c == ' ' || (c >= '\t' && c <= '\r'); }

}  // namespace

LineReader::LineReader(std::string path, std::size_t block)
    : path_(std::move(path)), capacity_(std::max<std::size_t>(block, 1)) {
  // A directory opens as an empty stream on Linux: name it rather than report an empty file.
  std::error_code ec;
  if (std::filesystem::is_directory(path_, ec)) throw InputError(path_, 0, "is a directory, not a file");
  file_.reset(std::fopen(path_.c_str(), "rb"));
  if (!file_) throw InputError(path_, 0, "cannot open file");
  std::setvbuf(file_.get(), nullptr, _IONBF, 0);  // the reads go straight into buf_, not through stdio's buffer
  // A pipe is read whole at once: its lines cannot be counted apart (lines_left).
  bool seekable = std::filesystem::is_regular_file(path_, ec);
  if (seekable) {
    const auto size = std::filesystem::file_size(path_, ec);
    seekable = !ec;
    size_ = static_cast<std::size_t>(size);
  }
  // A small file gets a buffer of its size (it grows if the file does): the fuzzers
  // read thousands of files of a few bytes, and a sanitizer maps each 256 KiB apart.
  if (seekable) capacity_ = std::min(capacity_, std::max<std::size_t>(size_ + 1, 64));
  buf_.reset(new char[capacity_ + 1]);
  buf_[0] = '\0';
  if (!seekable) read_all();
}

namespace {

// The newlines in [at, end), counted 64 bytes at a time in a byte counter, a loop the
// compiler turns into vector compares (memchr stopped at every line: a header's check
// read the file at a few instructions a byte).
std::size_t count_newlines(const char* at, const char* const end) {
  std::size_t lines = 0;
  for (; end - at >= 64; at += 64) {
    unsigned char block = 0;
    for (int k = 0; k < 64; ++k) block = static_cast<unsigned char>(block + (at[k] == '\n'));
    lines += block;
  }
  for (; at != end; ++at) lines += *at == '\n';
  return lines;
}

}  // namespace

std::size_t LineReader::refill(std::size_t i) {
  // The line from i has no newline in the buffer: it moves to the front, the rest of the
  // buffer is filled, until a newline comes (the buffer doubled for a longer line) or the file ends.
  const std::size_t keep = i < end_ ? end_ - i : 0;
  std::memmove(buf_.get(), buf_.get() + i, keep);
  base_ += end_ - keep;
  end_ = keep;
  whole_until_ = 0;
  while (whole_until_ == 0) {
    if (end_ == capacity_) grow();
    const std::size_t from = end_;
    end_ += std::fread(buf_.get() + end_, 1, capacity_ - end_, file_.get());
    if (end_ == from) {  // the end of the file (a read error too, as a short file, as before)
      eof_ = true;
      break;
    }
    for (std::size_t k = end_; k > from; --k)
      if (buf_[k - 1] == '\n') {
        whole_until_ = k;
        break;
      }
  }
  buf_[end_] = '\0';
  return 0;
}

void LineReader::grow() {
  std::unique_ptr<char[]> bigger(new char[2 * capacity_ + 1]);
  std::memcpy(bigger.get(), buf_.get(), end_);
  buf_ = std::move(bigger);
  capacity_ *= 2;
}

void LineReader::read_all() {
  for (;;) {
    if (end_ == capacity_) grow();
    const std::size_t got = std::fread(buf_.get() + end_, 1, capacity_ - end_, file_.get());
    if (got == 0) break;
    end_ += got;
  }
  eof_ = true;
  buf_[end_] = '\0';
  size_ = end_;
}

namespace {

// What a byte does to the split, by table (a load and a compare per byte): the loops below
// stop only at the end of a token, of a line or of the text. NUL ends the string's
// text (std::string keeps one past its end) and is token text inside it.
enum ByteClass : unsigned char { kToken, kSpace, kNewline, kHash, kNul };
struct ByteClasses {
  unsigned char of[256];
  constexpr ByteClasses() : of() {
    for (int c = 0; c < 256; ++c) of[c] = is_space(static_cast<char>(c)) ? kSpace : kToken;
    of[static_cast<unsigned char>('\n')] = kNewline;
    of[static_cast<unsigned char>('#')] = kHash;
    of[0] = kNul;
  }
};
constexpr ByteClasses kByteClasses;

}  // namespace

bool LineReader::next(std::vector<std::string_view>& tokens) {
  tokens.clear();
  // One pass over each line: tokens end at a space (a newline is one), a '#' ends the
  // line's content. (A search for the newline, then for '#', then the split, each went
  // over the line: reading a mesh is mostly this loop.) Each line is whole in the
  // buffer before it is split: the loops below stop at its newline or the file's end.
  std::size_t i = pos_;
  for (;;) {
    i = whole_line(i);
    const char* const text = buf_.get();
    const std::size_t size = end_;
    if (i >= size) break;  // the end of the file
    auto cls = [text](std::size_t k) { return kByteClasses.of[static_cast<unsigned char>(text[k])]; };
    ++line_;
    for (;;) {
      while (cls(i) == kSpace) ++i;
      if (cls(i) == kNul && i < size) {  // NUL inside the text: token text
      } else if (cls(i) != kToken) {
        if (cls(i) == kHash) {
          const void* newline = std::memchr(text + i, '\n', size - i);
          i = newline ? static_cast<std::size_t>(static_cast<const char*>(newline) - text) : size;
        }
        break;  // at the newline or the end
      }
      const std::size_t start = i;
      for (;;) {
        while (cls(i) == kToken) ++i;
        if (cls(i) != kNul || i >= size) break;
        ++i;  // NUL inside the text
      }
      tokens.emplace_back(text + start, i - start);
    }
    ++i;  // past the newline (or the end)
    if (!tokens.empty()) break;
  }
  pos_ = i;
  return !tokens.empty();
}

bool LineReader::plain(const char* kinds, std::int64_t* ints, double* reals) {
  pos_ = whole_line(pos_);  // the same place in the file, the line whole in the buffer
  const char* const text = buf_.get();
  const std::size_t size = end_;
  if (pos_ >= size) return false;
  auto cls = [text](std::size_t i) { return kByteClasses.of[static_cast<unsigned char>(text[i])]; };
  // A field ends at a space, the newline or the end of the text (not at a '#' or a NUL
  // inside the text: those lines take the general path).
  auto ends = [&](std::size_t i) { return cls(i) == kSpace || cls(i) == kNewline || i == size; };
  std::size_t i = pos_;
  for (const char* kind = kinds; *kind; ++kind) {
    while (cls(i) == kSpace) ++i;
    const std::size_t start = i;
    if (*kind == 'i') {
      const bool minus = text[i] == '-';
      if (minus) ++i;
      std::int64_t v = 0;
      const std::size_t digits_from = i;
      // Digits past the 18th are counted, not added: 19 of them could overflow, and
      // such a number takes the general path anyway.
      for (unsigned d; (d = static_cast<unsigned char>(text[i]) - static_cast<unsigned>('0')) <= 9; ++i)
        if (i - digits_from < 18) v = v * 10 + static_cast<std::int64_t>(d);
      if (i == digits_from || i - digits_from > 18 || !ends(i)) return false;
      *ints++ = minus ? -v : v;
    } else if (*kind == 'r') {
      double v = 0;
      const auto [end, error] = std::from_chars(text + i, text + size, v);
      i = static_cast<std::size_t>(end - text);
      if (error != std::errc() || i == start || !ends(i) || !std::isfinite(v)) return false;
      *reals++ = v;
    } else {
      while (cls(i) == kToken) ++i;
      if (i == start || !ends(i)) return false;
    }
  }
  while (cls(i) == kSpace) ++i;
  if (cls(i) != kNewline && i != size) return false;
  ++line_;
  pos_ = i + 1;  // past the newline (or the end), as next() leaves it
  return true;
}

void LineReader::expect(std::vector<std::string_view>& tokens, const std::string& what) {
  if (!next(tokens)) fail(fmt::format("unexpected end of file: expected {}", what));
}

void LineReader::expect_item(std::vector<std::string_view>& tokens, const char* item, std::size_t i, std::size_t n) {
  if (!next(tokens)) fail(fmt::format("unexpected end of file: expected {} {} of {}", item, i, n));
}

std::size_t LineReader::lines_left() const { return lines_from(base_ + pos_); }

std::string LineReader::too_many(const char* what, std::int64_t n, std::size_t left) {
  return fmt::format("{} is {} but the file has only {} more lines", what, n, left);
}

std::size_t LineReader::bytes_left() const {
  const std::size_t at = base_ + pos_;
  return at < size_ ? size_ - at : 0;
}

std::size_t LineReader::lines_from(std::size_t offset) const {
  // The newlines in the buffer from offset, then in the rest of the file, read through a
  // small buffer of its own and the file's place restored: the tokens stay valid. (An
  // offset before the buffer: the file from there.)
  const bool in_buffer = offset >= base_;
  const bool buffered = in_buffer && offset - base_ < end_;
  std::size_t lines = buffered ? count_newlines(buf_.get() + (offset - base_), buf_.get() + end_) : 0;
  bool more = false;
  if (!eof_ || !in_buffer) {
    const long at = std::ftell(file_.get());
    if (!in_buffer && std::fseek(file_.get(), static_cast<long>(offset), SEEK_SET) != 0)
      throw InputError(path_, line_, "cannot read the file again (seek)");
    // Not zeroed: fread writes what is counted (zeroing 64 KiB was 4 % of fuzz_parse,
    // page faults of the sanitizer's fresh memory, for files of a few bytes).
    // A small file's rest gets a block of its size (one byte more, to see the end): 64 KiB
    // each time was 60 % of the bytes fuzz_parse allocated, fresh pages under ASan.
    constexpr std::size_t kCountBlock = std::size_t{1} << 16;
    const std::size_t rest = size_ > offset ? size_ - offset : 0;
    const std::size_t block_size = std::clamp<std::size_t>(rest + 1, 64, kCountBlock);
    const std::unique_ptr<char[]> block(new char[block_size]);
    for (std::size_t got; (got = std::fread(block.get(), 1, block_size, file_.get())) > 0;) {
      lines += count_newlines(block.get(), block.get() + got);
      more = true;
    }
    std::clearerr(file_.get());
    if (at < 0 || std::fseek(file_.get(), at, SEEK_SET) != 0) throw InputError(path_, line_, "cannot read the file again (seek)");
  }
  return buffered || more ? lines + 1 : 0;
}

void LineReader::count_later(std::size_t n, const char* what) {
  pending_n_ = 0;
  // More items than bytes left (a line is at least one): certainly too many, counted now.
  if (n > bytes_left() + 1) {
    const std::size_t left = lines_left();
    if (n > left) fail(too_many(what, static_cast<std::int64_t>(n), left));
  }
  pending_n_ = n;
  pending_line_ = line_;
  pending_offset_ = base_ + pos_;
  pending_what_ = what;
}

void LineReader::check_pending_count() const {
  if (pending_n_ == 0) return;
  const std::size_t left = lines_from(pending_offset_);
  if (pending_n_ > left)
    throw InputError(path_, pending_line_, too_many(pending_what_, static_cast<std::int64_t>(pending_n_), left));
}

void LineReader::fail(const std::string& what) const {
  check_pending_count();
  throw InputError(path_, line_, what);
}
void LineReader::fail_at(int line, const std::string& what) const {
  check_pending_count();
  throw InputError(path_, line, what);
}

double LineReader::real(std::string_view token, const char* what) const {
  // Fast path: a plain finite decimal std::from_chars reads whole gives the value strtod
  // gives (both round correctly to nearest). Anything else (a sign '+', hexadecimal,
  // out of range, inf, nan, trailing bytes) takes strtod's path, so values and messages stay as before.
  {
    double v = 0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), v);
    if (error == std::errc() && end == token.data() + token.size() && std::isfinite(v)) return v;
  }
  std::string s(token);
  char* end = nullptr;
  errno = 0;
  double v = std::strtod(s.c_str(), &end);
  if (end == s.c_str() || end != s.c_str() + s.size()) fail(fmt::format("{} '{}' is not a number", what, printable(s)));
  if (errno == ERANGE && std::isinf(v)) fail(fmt::format("{} '{}' is too large for a double (overflows)", what, printable(s)));
  if (!std::isfinite(v)) fail(fmt::format("{} '{}' is not finite (NaN or infinite)", what, printable(s)));
  return v;  // subnormals and underflow to zero are accepted as written
}

std::int64_t LineReader::integer(std::string_view token, const char* what) const {
  {  // a plain decimal of at most 18 digits (an optional '-'): no overflow, the value from_chars gives
    const bool minus = !token.empty() && token[0] == '-';
    const std::size_t digits = token.size() - (minus ? 1 : 0);
    if (digits >= 1 && digits <= 18) {
      std::int64_t v = 0;
      bool plain = true;
      for (std::size_t i = minus ? 1 : 0; i < token.size() && plain; ++i) {
        const unsigned d = static_cast<unsigned char>(token[i]) - static_cast<unsigned>('0');
        plain = d <= 9;
        v = v * 10 + static_cast<std::int64_t>(d);
      }
      if (plain) return minus ? -v : v;
    }
  }
  {  // fast path, as in real(): only what strtoll reads the same way
    long long v = 0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), v);
    if (error == std::errc() && end == token.data() + token.size()) return v;
  }
  std::string s(token);
  char* end = nullptr;
  errno = 0;
  long long v = std::strtoll(s.c_str(), &end, 10);
  if (end == s.c_str() || end != s.c_str() + s.size()) fail(fmt::format("{} '{}' is not an integer", what, printable(s)));
  if (errno == ERANGE) fail(fmt::format("{} '{}' is out of range", what, printable(s)));
  return v;
}

void LineReader::fields(const std::vector<std::string_view>& tokens, std::size_t min, std::size_t max,
                        const char* what) const {
  if (tokens.size() < min)
    fail(fmt::format("{}: expected {} fields, found {}", what, min, tokens.size()));
  if (tokens.size() > max)
    fail(fmt::format("{}: expected at most {} fields, found {} (extra fields)", what, max, tokens.size()));
}

}  // namespace lepp::detail
