// SPDX-License-Identifier: GPL-3.0-or-later
// How a fuzz target reports a finding (a crash-worthy fact: a loop, a mismatch,
// an uncaught exception). Under libFuzzer it prints one line naming the class
// and aborts, so the input is saved; under the replay driver's --expect-finding
// mode it throws instead, so known-open findings can be replayed as tests.
#pragma once
#include <stdexcept>
#include <string>

namespace lepp::fuzz {

// Thrown by report_finding() when the replay driver expects findings.
struct FindingReported : std::runtime_error {
  std::string finding_class;
  FindingReported(std::string cls, const std::string& what) : std::runtime_error(what), finding_class(std::move(cls)) {}
};

// Prints "LEPP-FINDING target=... class=... : message" to stderr, then aborts
// (or throws FindingReported in replay-expect mode). Classes listed in the
// environment variable LEPP_FUZZ_IGNORE (comma separated) are printed and not
// aborted on, so a long run can keep hunting after a known class.
void report_finding(const char* target, const std::string& finding_class, const std::string& message);

// Set by the replay driver: findings throw instead of aborting.
void set_expect_findings(bool on);
bool expecting_findings();

}  // namespace lepp::fuzz
