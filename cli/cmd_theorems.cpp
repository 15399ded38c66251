// SPDX-License-Identifier: GPL-3.0-or-later
// `lepp theorems [--long] [--out docs/THEOREMS.md] [--only Suite.Name]`: re-runs
// the paper's statements as RapidCheck properties (properties/theorems) and
// prints the certificate table; exit 0 when every row holds or is a documented
// finding whose narrowed statement holds, 1 otherwise. With `--prove`, each row is
// also decided for all configurations (properties/prove: proved, refuted by a
// confirmed exact counterexample, or not decided and why) in a "decided" column;
// `--tight` adds the tight constants, `--write-proofs DIR` the obligation files.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "lepp/prove/certificate.h"
#include "message.h"

namespace lepp::cli {
namespace {

struct TheoremsArgs {
  prove::CertificateRequest request;
  std::string out;
  std::string write_proofs;
};

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

void add_theorems_command(CLI::App& app, int& status) {
  auto args = std::make_shared<TheoremsArgs>();
  auto* cmd = app.add_subcommand("theorems", "Re-run the paper's theorems as properties and print the certificate table");
  cmd->add_flag("--long", args->request.long_run, "The long run (more cases, more PSLGs)");
  cmd->add_option("--out", args->out, "Also write the certificate (Markdown) to this file, e.g. docs/THEOREMS.md");
  cmd->add_option("--only", args->request.only, "Run only these statements (Suite.Name)");
  cmd->add_option("--seed", args->request.seed, "RapidCheck seed (default: the fixed seed of the certificate)");
  cmd->add_flag("--prove", args->request.prove,
                "Also decide every row for all configurations (Z3; Lemma 7 (I) by MPFI interval boxes): proved, "
                "refuted by an exact counterexample, or not decided and why (the \"decided\" column)");
  cmd->add_option("--time-limit", args->request.time_limit,
                  "With --prove: seconds per solver call and per branch-and-bound (default 30)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--tight-time-limit", args->request.tight_time_limit,
                  "With --tight: seconds per solver call of the bisection (default 10)")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--tight", args->request.tight,
                "With --prove: the tight constants (bisection: largest value proved, smallest refuted within 1e-6)");
  cmd->add_option("--write-proofs", args->write_proofs,
                  "With --prove: write the obligation files (SMT-LIB 2, QEPCAD B) into this directory, e.g. "
                  "corpus/theorems/proofs");
  cmd->add_option("--pictures", args->request.pictures,
                  "With --prove: draw every refuted row's counterexample (SVG, exact coordinates) into this directory, "
                  "linked from the table, e.g. docs/theorems");
  cmd->add_option("--corpus", args->request.corpus,
                  "With --prove: the sampled counterexamples' directory (default corpus/theorems)");
  cmd->callback([args, &status] { status = run_theorems(*args); });
}

}  // namespace lepp::cli
