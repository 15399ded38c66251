// SPDX-License-Identifier: GPL-3.0-or-later
// The exit statuses every lepp program gives its command line (lepp, and its helper
// lepp-theorems, which parses the same options): a usage error is bad input (2, CLI11's
// message), an exception that escapes a command is an internal error (1), else the
// command's own status.
#pragma once
#include <exception>

#include <CLI/CLI.hpp>

#include "message.h"

namespace lepp::cli {

inline int parse_and_run(CLI::App& app, int argc, char** argv, const int& status) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;  // --help and --version end here too, with 0
  } catch (const std::exception& e) {
    message("lepp: internal error: %s\n", e.what());
    return 1;
  }
  return status;
}

}  // namespace lepp::cli
