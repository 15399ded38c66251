// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind shell_command.h: running another program through /bin/sh, for the
// comparisons (Triangle under node, the plot script, lepp render).
#include "shell_command.h"

#include <sys/wait.h>

#include <cstdio>

namespace lepp::others {

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

int run_shell(const std::string& command, std::string& output) {
  output.clear();
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return -1;
  char buf[4096];
  std::size_t n;
  while ((n = fread(buf, 1, sizeof buf, pipe)) > 0) output.append(buf, n);
  int status = pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace lepp::others
