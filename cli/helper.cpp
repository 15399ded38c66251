// SPDX-License-Identifier: GPL-3.0-or-later
// Helper programs beside the executable (helper.h).
#include "helper.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace fs = std::filesystem;

namespace lepp::cli {
namespace {

std::vector<fs::path> helper_dirs() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  const fs::path bin = exe.parent_path();
  // LEPP_HELPER_DIR: the install's helper directory relative to its bin/ (cli/CMakeLists.txt).
  return {bin, (bin / LEPP_HELPER_DIR).lexically_normal()};
}

}  // namespace

std::string helper_search_path() {
  std::string r;
  for (const fs::path& d : helper_dirs()) r += (r.empty() ? "" : ", ") + d.string();
  return r.empty() ? "nowhere: /proc/self/exe is unreadable" : r;
}

void exec_helper(const char* name, char** argv, std::string* error) {
  for (const fs::path& d : helper_dirs()) {
    const fs::path helper = d / name;
    std::error_code ec;
    if (!fs::is_regular_file(helper, ec)) continue;
    std::fflush(nullptr);
    execv(helper.c_str(), argv);
    *error = "cannot run " + helper.string() + ": " + std::strerror(errno);
    return;
  }
  *error = std::string(name) + " is missing (looked in " + helper_search_path() +
           "): it is built and installed with lepp";
}

}  // namespace lepp::cli
