// SPDX-License-Identifier: GPL-3.0-or-later
// lepp-theorems: the program that runs `lepp theorems`. `lepp` checks the command
// line, then executes this program with the same arguments (cmd_theorems.cpp), so
// that only this command loads Z3 and MPFI (helper.h). It parses the same options
// (theorems_options.h), calls properties/prove (the certificate) and prints:
// progress on stderr, one line per row, the table on stdout; exit 0 when every row
// holds or is a documented finding whose narrowed statement holds, 1 otherwise,
// 2 bad input.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "lepp/prove/certificate.h"
#include "message.h"
#include "run_app.h"
#include "theorems_options.h"

namespace lepp::cli {
namespace {

int run_theorems(const TheoremsArgs& args) {
  if (!args.write_proofs.empty() && !std::filesystem::is_directory(args.write_proofs)) {
    message("lepp theorems: --write-proofs %s: not a directory\n", args.write_proofs.c_str());
    return 2;
  }
  prove::CertificateRequest request = args.request;
  request.table_path = args.out;
  prove::CertificateProgress progress;
  progress.started = [](const std::string& step, const std::string& id) {
    // One line per row: the step's name is its width, the result follows on the line.
    if (step == "sample") message("%-70s ", id.c_str());
    else message("%s %-*s ", step.c_str(), 69 - static_cast<int>(step.size()), id.c_str());
    std::fflush(stderr);
  };
  progress.finished = [](const std::string& result, const std::string& detail) {
    message("%s\n", result.c_str());
    if (!detail.empty()) message("    %s\n", detail.c_str());
  };
  prove::CertificateRun run;
  std::string error;
  if (!prove::run_certificate(request, progress, &run, &error)) {
    message("lepp theorems: %s\n", error.c_str());
    return 2;
  }
  if (!args.write_proofs.empty() && !prove::write_obligation_files(args.write_proofs, run.decisions, &error)) {
    message("lepp theorems: %s\n", error.c_str());
    return 2;
  }
  if (!args.out.empty()) {
    std::string previous;
    if (std::ifstream old(args.out); old) previous.assign(std::istreambuf_iterator<char>(old), {});
    std::ofstream f(args.out);
    if (!(f << prove::certificate_document(request, run, previous))) {
      message("lepp theorems: cannot write %s\n", args.out.c_str());
      return 2;
    }
  }
  std::fputs(run.table.c_str(), stdout);
  if (!run.tight_table.empty()) std::fputs(("\n" + run.tight_table).c_str(), stdout);
  return run.ok ? 0 : 1;
}

}  // namespace
}  // namespace lepp::cli

int main(int argc, char** argv) {
  // The command line `lepp` was given, parsed as `lepp` parses it (main.cpp).
  CLI::App app{"lepp theorems: the paper's theorems as properties, and decided (Z3, MPFI)", "lepp"};
  app.require_subcommand(1, 1);
  lepp::cli::TheoremsArgs args;
  int status = 0;
  lepp::cli::add_theorems_subcommand(app, args)->callback([&] { status = lepp::cli::run_theorems(args); });
  return lepp::cli::parse_and_run(app, argc, argv, status);
}
