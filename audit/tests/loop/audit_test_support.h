// SPDX-License-Identifier: GPL-3.0-or-later
// What the audit_tests' files share: the small audit they run lepp's engines
// (and broken ones) through, and reading a file back whole.
#pragma once
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "lepp/audit/audit.h"

namespace lepp::audit::test {

// Twelve generated inputs of size at most 20 (seed 7) at 25 degrees, no paper
// or corpus inputs, findings under the temporary directory in `out`-PID: per
// process, as other checkouts may run the same tests at the same time.
inline AuditOptions small_audit(const std::string& out) {
  AuditOptions o;
  o.thetas = {25};
  o.cases = 12;
  o.inputs.paper = o.inputs.corpus = false;
  o.inputs.max_size = 20;
  o.inputs.seed = 7;
  o.timeout_seconds = 20;
  o.out_dir = (std::filesystem::temp_directory_path() / (out + "-" + std::to_string(getpid()))).string();
  return o;
}

// The whole file ("" when it cannot be read).
inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace lepp::audit::test
