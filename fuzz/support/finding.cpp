// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind finding.h: how a fuzz target reports a finding (a loop, a mismatch, an uncaught exception).
#include "finding.h"

#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace lepp::fuzz {

namespace {
bool expect_findings = false;

bool ignored(const std::string& finding_class) {
  const char* env = std::getenv("LEPP_FUZZ_IGNORE");
  if (!env) return false;
  std::stringstream list(env);
  std::string item;
  while (std::getline(list, item, ','))
    if (item == finding_class) return true;
  return false;
}
}  // namespace

void set_expect_findings(bool on) { expect_findings = on; }
bool expecting_findings() { return expect_findings; }

void report_finding(const char* target, const std::string& finding_class, const std::string& message) {
  std::fprintf(stderr, "LEPP-FINDING target=%s class=%s : %s\n", target, finding_class.c_str(), message.c_str());
  if (expect_findings) throw FindingReported(finding_class, message);
  if (ignored(finding_class)) return;
  std::fflush(stderr);
  std::abort();
}

}  // namespace lepp::fuzz
