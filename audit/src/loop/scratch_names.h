// SPDX-License-Identifier: GPL-3.0-or-later
// The names of the audit's scratch directories, TMPDIR/lepp-audit-XXXXXX/run-W-K/:
// loop/session.cpp makes them, and report/finding.cpp takes them out of the words
// it saves (they are gone when the audit ends). One place for both.
#pragma once
#include <cstddef>
#include <regex>
#include <string>

#include <fmt/format.h>

namespace lepp::audit::loop {

// mkdtemp's template of the scratch root, under the system's temp directory.
inline constexpr const char* kScratchRootTemplate = "lepp-audit-XXXXXX";

// The directory of worker w's k-th run slot under the root.
inline std::string run_dir_name(std::size_t worker, std::size_t slot) { return fmt::format("run-{}-{}", worker, slot); }

// A run directory under a root made from kScratchRootTemplate, written as a path
// with its trailing '/': what a program's file names start with there.
inline const std::regex& run_dir_pattern() {
  static const std::regex pattern = [] {
    const std::string root = kScratchRootTemplate;
    const std::string prefix = root.substr(0, root.find('X'));
    const std::size_t random = root.size() - prefix.size();  // mkdtemp's letters and digits
    return std::regex(fmt::format(R"([^\s'"(]*/{}[A-Za-z0-9]{{{}}}/run-[0-9]+-[0-9]+/)", prefix, random));
  }();
  return pattern;
}

}  // namespace lepp::audit::loop
