// SPDX-License-Identifier: GPL-3.0-or-later
// A message on stderr, printf-style, after stdout is flushed: with both sent to one
// file (`lepp paper > log 2>&1`), a message never lands inside a table row.
// Every subcommand writes to stderr through this.
#pragma once
#include <cstdarg>
#include <cstdio>

namespace lepp::cli {

#if defined(__GNUC__)
__attribute__((format(printf, 1, 2)))
#endif
inline void message(const char* format, ...) {
  std::fflush(stdout);
  va_list args;
  va_start(args, format);
  std::vfprintf(stderr, format, args);
  va_end(args);
}

}  // namespace lepp::cli
