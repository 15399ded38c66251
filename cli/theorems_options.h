// SPDX-License-Identifier: GPL-3.0-or-later
// The options of `lepp theorems`, defined once for the two programs that parse
// them: `lepp` (its help, its checks, then the hand-over, cmd_theorems.cpp) and
// `lepp-theorems`, the helper that runs the command (theorems_main.cpp).
#pragma once
#include <string>

#include <CLI/CLI.hpp>

#include "lepp/prove/certificate.h"  // CertificateRequest: types and defaults only, no link to Z3

namespace lepp::cli {

struct TheoremsArgs {
  prove::CertificateRequest request;
  std::string out;
  std::string write_proofs;
};

// Adds the `theorems` subcommand and its options to app; parsing fills *args.
CLI::App* add_theorems_subcommand(CLI::App& app, TheoremsArgs& args);

}  // namespace lepp::cli
