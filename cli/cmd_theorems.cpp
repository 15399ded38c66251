// Placeholder: `lepp theorems` lands with its issue.
#include <cstdio>

#include "commands.h"

namespace lepp::cli {

void add_theorems_command(CLI::App& app, int& status) {
  auto* cmd = app.add_subcommand("theorems", "(not implemented yet)");
  cmd->allow_extras();
  cmd->callback([&status] {
    std::fprintf(stderr, "lepp theorems: not implemented yet\n");
    status = 1;
  });
}

}  // namespace lepp::cli
