// SPDX-License-Identifier: GPL-3.0-or-later
// Splits a Triangle-format text file into lines of whitespace-separated tokens,
// dropping comments (# to end of line) and blank lines, and converts tokens to
// numbers with errors that name the file and line.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace lepp::detail {

class LineReader {
 public:
  // Throws InputError if the file cannot be opened.
  explicit LineReader(std::string path);

  // Next non-blank line's tokens; false at end of file.
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
  // Lines left to read, an upper bound on how many items a header may promise.
  std::size_t lines_left() const;

  [[noreturn]] void fail(const std::string& what) const;
  [[noreturn]] void fail_at(int line, const std::string& what) const;  // an earlier line
  double real(std::string_view token, const char* what) const;          // finite double
  std::int64_t integer(std::string_view token, const char* what) const;
  // Checks the field count of the last line: at least min, at most max.
  void fields(const std::vector<std::string_view>& tokens, std::size_t min, std::size_t max,
              const char* what) const;

 private:
  std::string path_;
  std::string text_;
  std::size_t pos_ = 0;
  int line_ = 0;
};

}  // namespace lepp::detail
