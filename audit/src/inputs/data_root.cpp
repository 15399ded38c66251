// SPDX-License-Identifier: GPL-3.0-or-later
// Where the built-in corpus is: --root, share/lepp beside the executable, the source tree.
#include "lepp/audit/inputs/data_root.h"

#include <filesystem>
#include <system_error>

namespace fs = std::filesystem;

namespace lepp::audit {
namespace {

bool has_corpus(const fs::path& root) {
  std::error_code ec;
  return fs::is_directory(root / "corpus" / "paper", ec) || fs::is_directory(root / "corpus" / "hostile", ec);
}

}  // namespace

std::string executable_path() {
  std::error_code ec;
  fs::path p = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : p.string();
}

std::string find_data_root(const std::string& given) {
  if (!given.empty()) return given;
  const std::string exe = executable_path();
  if (!exe.empty()) {
    const fs::path installed = fs::path(exe).parent_path().parent_path() / "share" / "lepp";
    if (has_corpus(installed)) return installed.lexically_normal().string();
  }
#ifdef LEPP_BUILD_SOURCE_DIR
  // A build tree: the sources it was built from (checked, so a moved build still falls through).
  if (has_corpus(LEPP_BUILD_SOURCE_DIR)) return LEPP_BUILD_SOURCE_DIR;
#endif
  return ".";
}

}  // namespace lepp::audit
