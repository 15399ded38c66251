// SPDX-License-Identifier: GPL-3.0-or-later
// `lepp audit` from its options: the engine under audit and the comparisons by name, then the rest.
#include "lepp/engines/audit_setup.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "lepp/audit/inputs/data_root.h"
#include "lepp/audit/run/subprocess.h"
#include "lepp/engines/audited_engines.h"
#include "lepp/engines/command_engine.h"
#include "lepp/engines/registry.h"
#include "lepp/version.h"

namespace lepp::engines {
AuditSetup audit_setup(const audit::AuditRequest& request) {
  audit::AuditRequest a = request;
  if (a.cmd.empty() == a.engine.empty()) throw audit::UsageError("give exactly one of --cmd TEMPLATE and --engine NAME");
  a.root = audit::find_data_root(a.root);
  // reproduce.sh names this very lepp: a bare `lepp` may not be on PATH, or be another one.
  const std::string self = audit::executable_path();
  const std::string lepp_word = self.empty() ? "lepp" : audit::shell_quote(self);
  AuditSetup setup;
  audit::AuditOptions& o = setup.options;
  // The options' checks admit only the registry's names.
  o.method = *parse_method(a.method);
  const QueueOrder order = *parse_order(a.order);
  // lepp's engines in a child process unless --no-isolate (CGAL's always is: peer_engines.h).
  const bool isolate = !a.no_isolate;
  if (!a.cmd.empty()) {
    setup.engine = audit::command_engine(a.cmd);
    o.engine_name = a.cmd;
    o.reproduce_prefix = lepp_word + " audit --cmd " + audit::shell_quote(a.cmd);
  } else {
    const Engine which = *parse_engine(a.engine, audit_engines());
    setup.engine = audited_engine(which, order, isolate, a.root, a.tie_search_states);
    o.engine_name = audit_title(which, order);
    o.reproduce_prefix = lepp_word + " audit --engine " + a.engine +
                         (order == QueueOrder::Fifo ? "" : std::string(" --order ") + lepp::to_string(order));
    if (which == Engine::Triangle)
      o.reproduce_prefix += " --root " + audit::shell_quote(std::filesystem::absolute(a.root).string());
  }
  const bool automatic = a.compare == "auto";
  const std::vector<std::string> compare = automatic ? names(auto_comparisons()) : audit::comma_list(a.compare);
  for (const std::string& c : compare) {
    if (c == "none") continue;
    const std::optional<Engine> which = parse_engine(c, comparison_engines());
    if (!which)
      throw audit::UsageError("--compare: unknown engine " + c + " (" + fmt::format("{}", fmt::join(names(comparison_engines()), ", ")) + ", none)");
    // Cache keys name the engine's build: a new lepp or Triangle budget is a new entry.
    const std::string build = fmt::format("{} {}", kVersion, git_commit());
    try {
      o.comparisons.push_back(comparison_engine(*which, isolate, a.root, build, a.tie_search_states));
    } catch (const audit::UsageError&) {
      // Triangle missing: asked for explicitly, say so; under auto, compare without it.
      if (!automatic || *which != Engine::Triangle) throw;
    }
  }
  audit::apply_request(a, o);
  return setup;
}

}  // namespace lepp::engines
