// SPDX-License-Identifier: GPL-3.0-or-later
// `lepp theorems [--long] [--out docs/THEOREMS.md] [--only Suite.Name]`: re-runs
// the paper's statements as RapidCheck properties (properties/theorems) and
// prints the certificate table; exit 0 when every row holds or is a documented
// finding whose narrowed statement holds, 1 otherwise. With `--prove`, each row is
// also decided for all configurations (properties/prove: proved, refuted by a
// confirmed exact counterexample, or not decided and why) in a "decided" column;
// `--tight` adds the tight constants, `--write-proofs DIR` the obligation files.
// Here the options are parsed (help, usage errors); the run is the helper program
// lepp-theorems (theorems_main.cpp), executed with the same arguments, so that
// Z3 stays out of every other command's start (helper.h).
#include <memory>
#include <string>

#include "commands.h"
#include "helper.h"
#include "message.h"
#include "theorems_options.h"

namespace lepp::cli {

void add_theorems_command(CLI::App& app, int& status, char** argv) {
  auto args = std::make_shared<TheoremsArgs>();
  add_theorems_subcommand(app, *args)->callback([args, argv, &status] {  // args: the options write into it
    std::string error;
    exec_helper(kTheoremsHelper, argv, &error);  // returns only when it could not
    message("lepp theorems: %s\n", error.c_str());
    status = 1;  // a broken install, not the user's input
  });
}

}  // namespace lepp::cli
