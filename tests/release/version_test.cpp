// SPDX-License-Identifier: GPL-3.0-or-later
// The version reaches the user: `lepp --version` prints the CMake project version (passed here
// by CMake, not copied from the header) and exits 0; every --json output carries "lepp_version".
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "lepp/version.h"

namespace {

namespace fs = std::filesystem;
const std::string kSource = LEPP_SOURCE_DIR;
const std::string kProjectVersion = LEPP_PROJECT_VERSION;  // ${PROJECT_VERSION} from CMake

struct CliResult {
  int status = -1;
  std::string out;
};

fs::path scratch() {
  fs::path dir = fs::temp_directory_path() / ("lepp_version_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

CliResult lepp(const std::string& args) {
  const fs::path out = scratch() / "stdout";
  const std::string cmd = std::string(LEPP_CLI) + " " + args + " > " + out.string() + " 2> /dev/null";
  const int raw = std::system(cmd.c_str());
  CliResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  std::ifstream in(out);
  std::stringstream s;
  s << in.rdbuf();
  r.out = s.str();
  return r;
}

// True when the first line of `lepp --version` is exactly "lepp VERSION".
bool names_version(const std::string& text, const std::string& version) {
  return text.substr(0, text.find('\n')) == "lepp " + version;
}

TEST(Version, CheckerRejectsOtherVersions) {
  EXPECT_TRUE(names_version("lepp 1.2.3\ncommit x\n", "1.2.3"));
  EXPECT_FALSE(names_version("lepp 1.2.30\ncommit x\n", "1.2.3"));
  EXPECT_FALSE(names_version("lepp 1.2\n", "1.2.3"));
  EXPECT_FALSE(names_version("", "1.2.3"));
}

TEST(Version, HeaderAgreesWithCMakeProject) { EXPECT_EQ(lepp::kVersion, kProjectVersion); }

TEST(Version, CommandPrintsProjectVersionCommitAndLibraries) {
  const CliResult r = lepp("--version");
  EXPECT_EQ(r.status, 0);
  EXPECT_TRUE(names_version(r.out, kProjectVersion)) << r.out;
  EXPECT_NE(r.out.find("\ncommit "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("CGAL " + std::string(lepp::cgal_version())), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("GMP " + std::string(lepp::gmp_version_built())), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("MPFR " + std::string(lepp::mpfr_version_built())), std::string::npos) << r.out;
}

TEST(Version, JsonOutputsCarryLeppVersion) {
  const std::string poly = kSource + "/corpus/paper/A.poly";
  const std::string prefix = (scratch() / "A").string();
  const CliResult refine = lepp("refine " + poly + " -o " + prefix + " --min-angle 25 --json");
  ASSERT_EQ(refine.status, 0) << refine.out;
  const nlohmann::json r = nlohmann::json::parse(refine.out);
  ASSERT_TRUE(r.contains("lepp_version")) << refine.out;
  EXPECT_EQ(r["lepp_version"], kProjectVersion);

  const CliResult certify = lepp("certify " + poly + " " + prefix + " --min-angle 25 --json");
  ASSERT_EQ(certify.status, 0) << certify.out;
  const nlohmann::json c = nlohmann::json::parse(certify.out);
  ASSERT_TRUE(c.contains("lepp_version")) << certify.out;
  EXPECT_EQ(c["lepp_version"], kProjectVersion);
}

TEST(Version, AddVersionStampsAnyJsonObject) {
  nlohmann::json j = {{"x", 1}};
  lepp::add_version(j);
  EXPECT_EQ(j["lepp_version"], kProjectVersion);
  EXPECT_EQ(j["x"], 1);
}

}  // namespace
