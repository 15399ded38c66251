// SPDX-License-Identifier: GPL-3.0-or-later
// lepp: quality triangulation by the Lepp-centroid method, and the tools to prove it right.
#include <string>

#include "commands.h"
#include "run_app.h"
#include "lepp/version.h"

int main(int argc, char** argv) {
  CLI::App app{"lepp: Lepp-centroid quality triangulation, an exact reference engine, and a mesh certifier"};
  app.require_subcommand(1, 1);
  app.set_help_all_flag("--help-all", "Show help for every subcommand");
  // `lepp --version`: version, git commit, CGAL/GMP/MPFR versions on stdout, exit 0.
  std::string version = lepp::version_text();
  version.pop_back();  // CLI11 adds the final newline
  app.set_version_flag("--version", version, "Print lepp's version, git commit, and the CGAL, GMP, MPFR versions");
  int status = 0;
  lepp::cli::add_refine_command(app, status);
  lepp::cli::add_certify_command(app, status);
  lepp::cli::add_render_command(app, status);
  lepp::cli::add_paper_command(app, status);
  lepp::cli::add_theorems_command(app, status, argv);
  lepp::cli::add_audit_command(app, status);
  return lepp::cli::parse_and_run(app, argc, argv, status);
}
