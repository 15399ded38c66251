// Placeholder: `lepp render` lands with its issue.
#include <cstdio>

#include "commands.h"

namespace lepp::cli {

void add_render_command(CLI::App& app, int& status) {
  auto* cmd = app.add_subcommand("render", "(not implemented yet)");
  cmd->allow_extras();
  cmd->callback([&status] {
    std::fprintf(stderr, "lepp render: not implemented yet\n");
    status = 1;
  });
}

}  // namespace lepp::cli
