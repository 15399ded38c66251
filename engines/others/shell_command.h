// SPDX-License-Identifier: GPL-3.0-or-later
// Running another program through /bin/sh, for the comparisons (Triangle under
// node, the plot script, lepp render): one quoting rule, one way to read its output.
#pragma once
#include <string>

namespace lepp::others {

// s in single quotes for /bin/sh, its own single quotes escaped.
std::string shell_quote(const std::string& s);

// Runs a shell command, its stdout into `output`; returns the exit status (-1 if it did not exit).
int run_shell(const std::string& command, std::string& output);

}  // namespace lepp::others
