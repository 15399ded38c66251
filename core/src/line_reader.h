// SPDX-License-Identifier: GPL-3.0-or-later
// Splits a Triangle-format text file into lines of whitespace-separated tokens,
// dropping comments (# to end of line) and blank lines, and converts tokens to
// numbers with errors that name the file and line. The file is read through a buffer of
// fixed size, parsed as it comes: a mesh's text is never held whole (at 10^7 triangles
// that was half a gigabyte of freshly touched pages, issue 40).
#pragma once
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace lepp::detail {

class LineReader {
 public:
  // The buffer's size: a line longer than it grows the buffer to hold that line.
  static constexpr std::size_t kBlock = std::size_t{1} << 18;
  // Throws InputError if the file cannot be opened. `block`: the buffer's size (the tests
  // make it a few bytes, so that numbers and lines are split across reads).
  explicit LineReader(std::string path, std::size_t block = kBlock);

  // Next non-blank line's tokens; false at end of file. The tokens view the buffer: they
  // stay valid until the next call of next(), expect(), expect_item() or plain().
  bool next(std::vector<std::string_view>& tokens);
  // Like next(), but a missing line is an error saying what was expected.
  void expect(std::vector<std::string_view>& tokens, const std::string& what);
  // expect() for the i-th of n items ("triangle 5 of 9"): the message is formatted only
  // when the line is missing (a format per line was a tenth of reading a mesh).
  void expect_item(std::vector<std::string_view>& tokens, const char* item, std::size_t i, std::size_t n);
  // The next line if it is a plain item line, read without splitting it into tokens:
  // fields of the kinds in `kinds` ('i': an optional '-' and 1 to 18 digits, into ints;
  // 'r': a finite decimal std::from_chars reads whole, into reals; '-': any token, not
  // read), one each, separated by spaces, then the line's end. Anything else (a blank or
  // comment line, a '#', a NUL, another field count, a number in another form) returns
  // false with the reader unmoved: the caller then takes next() and the token readers,
  // whose values (strtod's) and messages are the same as for any line.
  bool plain(const char* kinds, std::int64_t* ints, double* reals);
  int line() const { return line_; }  // 1-based number of the last line returned
  const std::string& path() const { return path_; }
  // Lines left to read, an upper bound on how many items a header may promise. Counts
  // the rest of the file (read again through a small buffer of its own, the reader's
  // place and tokens untouched).
  std::size_t lines_left() const;
  // The error of a header that promises n items, `what`, with only `left` lines left:
  // one message for every reader and for count_later's check.
  static std::string too_many(const char* what, std::int64_t n, std::size_t left);
  // A header's count of items, n, one line each: an error unless n <= lines_left(), the
  // message of header_count's (read_poly.cpp's count's) check. When the file's size
  // allows n lines, the lines are not counted now (that read the whole file once more,
  // issue 40) but only if an error comes before the n items are read: fail() then reports
  // this header's error instead when the count is too large, as the check at the header did.
  void count_later(std::size_t n, const char* what);
  // The items were read: the count was right (n items took n lines at least).
  void count_kept() { pending_n_ = 0; }
  // An upper bound on the bytes left, from the file's size (no reading).
  std::size_t bytes_left() const;

  [[noreturn]] void fail(const std::string& what) const;  // the line's, or a count_later header's
  [[noreturn]] void fail_at(int line, const std::string& what) const;  // an earlier line
  double real(std::string_view token, const char* what) const;          // finite double
  std::int64_t integer(std::string_view token, const char* what) const;
  // Checks the field count of the last line: at least min, at most max.
  void fields(const std::vector<std::string_view>& tokens, std::size_t min, std::size_t max,
              const char* what) const;

 private:
  // Makes the line that starts at buf_[i] whole in the buffer (up to its newline, or
  // the end of the file), reading more when it is not; returns where it starts then.
  std::size_t whole_line(std::size_t i) { return i < whole_until_ || eof_ ? i : refill(i); }
  std::size_t refill(std::size_t i);
  void grow();  // doubles the buffer, its bytes kept
  // Reads the rest of the file into the buffer (a pipe, whose lines cannot be counted apart).
  void read_all();
  // The lines of the file from byte `offset` on (lines_left's count).
  std::size_t lines_from(std::size_t offset) const;
  // Throws the count_later header's error if its count is too large.
  void check_pending_count() const;

  std::string path_;
  struct Close {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  std::unique_ptr<std::FILE, Close> file_;  // closed however the reader ends (a throwing constructor too)
  // buf_[0, end_) holds the file's bytes not yet consumed from pos_ on (and some before),
  // then a NUL (a sentinel the loops stop at); whole_until_ is one past the last '\n' in
  // it (0: none), so a line that starts before it is whole.
  std::unique_ptr<char[]> buf_;
  std::size_t capacity_ = 0;  // bytes buf_ holds, sentinel excluded
  std::size_t end_ = 0;
  std::size_t whole_until_ = 0;
  bool eof_ = false;
  std::size_t pos_ = 0;
  int line_ = 0;
  std::size_t base_ = 0;  // the file's offset of buf_[0]
  std::size_t size_ = 0;  // the file's size (a pipe: its bytes, read whole)
  // count_later's header: n (0: none), its line, the file's offset after it, what it counts.
  std::size_t pending_n_ = 0;
  int pending_line_ = 0;
  std::size_t pending_offset_ = 0;
  const char* pending_what_ = "";
};

}  // namespace lepp::detail
