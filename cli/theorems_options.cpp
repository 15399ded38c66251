// SPDX-License-Identifier: GPL-3.0-or-later
// The options of `lepp theorems` (theorems_options.h).
#include "theorems_options.h"

namespace lepp::cli {

CLI::App* add_theorems_subcommand(CLI::App& app, TheoremsArgs& args) {
  auto* cmd = app.add_subcommand("theorems", "Re-run the paper's theorems as properties and print the certificate table");
  cmd->add_flag("--long", args.request.long_run, "The long run (more cases, more PSLGs)");
  cmd->add_option("--out", args.out, "Also write the certificate (Markdown) to this file, e.g. docs/THEOREMS.md");
  cmd->add_option("--only", args.request.only, "Run only these statements (Suite.Name)");
  cmd->add_option("--seed", args.request.seed, "RapidCheck seed (default: the fixed seed of the certificate)");
  cmd->add_flag("--prove", args.request.prove,
                "Also decide every row for all configurations (Z3; Lemma 7 (I) by MPFI interval boxes): proved, "
                "refuted by an exact counterexample, or not decided and why (the \"decided\" column)");
  cmd->add_option("--time-limit", args.request.time_limit,
                  "With --prove: seconds per solver call and per branch-and-bound (default 30)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--tight-time-limit", args.request.tight_time_limit,
                  "With --tight: seconds per solver call of the bisection (default 10)")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--tight", args.request.tight,
                "With --prove: the tight constants (bisection: largest value proved, smallest refuted within 1e-6)");
  cmd->add_option("--write-proofs", args.write_proofs,
                  "With --prove: write the obligation files (SMT-LIB 2, QEPCAD B) into this directory, e.g. "
                  "corpus/theorems/proofs");
  cmd->add_option("--pictures", args.request.pictures,
                  "With --prove: draw every refuted row's counterexample (SVG, exact coordinates) into this directory, "
                  "linked from the table, e.g. docs/theorems");
  cmd->add_option("--corpus", args.request.corpus,
                  "With --prove: the sampled counterexamples' directory (default corpus/theorems)");
  return cmd;
}

}  // namespace lepp::cli
