// SPDX-License-Identifier: GPL-3.0-or-later
// A command whose libraries are heavy runs as a helper program beside `lepp`:
// `lepp theorems` needs Z3 (libz3: 23 MB, some 24,000 relocations) and MPFI,
// which every start of `lepp` paid for while only that command uses them, and
// the fuzzers and the audit start `lepp refine` once per input
// (docs/FUZZING.md, "Throughput"). `lepp` parses the command's options (its help,
// its usage errors), then executes the helper in its own process (exec: the same
// pid, standard streams and exit status) with the same arguments.
#pragma once
#include <string>

namespace lepp::cli {

inline constexpr const char* kTheoremsHelper = "lepp-theorems";

// The directories searched for a helper, in order: the executable's own (a build
// tree: cli/lepp beside cli/lepp-theorems), then the install's (bin/lepp and
// LIBEXECDIR/lepp/, as `cmake --install` and the Debian package lay them out).
std::string helper_search_path();

// Executes the helper `name` with argv (lepp's own, argv[0] included). Returns
// only when it could not, with *error naming the helper and the places searched.
void exec_helper(const char* name, char** argv, std::string* error);

}  // namespace lepp::cli
