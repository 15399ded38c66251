// SPDX-License-Identifier: GPL-3.0-or-later
// Where `lepp audit` finds its built-in inputs (corpus/paper, corpus/hostile)
// and Triangle (tools/triangle), wherever lepp is installed: the Debian
// packages put the corpus under share/lepp beside bin/lepp; a build tree has
// the source tree it was built from.
#pragma once
#include <string>

namespace lepp::audit {

// This program's absolute path (/proc/self/exe); empty when it cannot be read.
std::string executable_path();

// `given` when not empty (--root). Else the first that holds corpus/paper or
// corpus/hostile: EXE_DIR/../share/lepp (the installed layout), the source tree
// this lepp was built from; else "." (the sources then say they are missing).
std::string find_data_root(const std::string& given);

}  // namespace lepp::audit
