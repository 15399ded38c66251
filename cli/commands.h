// SPDX-License-Identifier: GPL-3.0-or-later
// Each `lepp` subcommand lives in its own file and registers itself here.
// A subcommand's callback stores its exit status in `status`:
// 0 success, 1 internal error or violations found, 2 bad input, 3 stopped/unimprovable.
#pragma once
#include <CLI/CLI.hpp>

namespace lepp::cli {

void add_refine_command(CLI::App& app, int& status);
void add_certify_command(CLI::App& app, int& status);
void add_render_command(CLI::App& app, int& status);
void add_paper_command(CLI::App& app, int& status);
void add_theorems_command(CLI::App& app, int& status, char** argv);  // runs lepp-theorems with argv
void add_audit_command(CLI::App& app, int& status);

}  // namespace lepp::cli
