// SPDX-License-Identifier: GPL-3.0-or-later
// Every file in corpus/bad/ is rejected with an InputError naming the file,
// the line marked "<- error" in it (or no line when none is marked), and a
// message containing the text on its first line ("# expect: ..."). An error
// at the end of the file names the file's last line.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "lepp/io.h"
#include "lepp/validate.h"

namespace lepp {
namespace {

const std::string kBad = LEPP_SOURCE_DIR "/corpus/bad/";

std::vector<std::string> bad_files() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(kBad))
    if (entry.path().extension() == ".poly") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

struct Expectation {
  std::string fragment;
  int line = 0;
};

Expectation expectation_of(const std::string& path) {
  std::ifstream in(path);
  std::string text;
  Expectation e;
  for (int line = 1; std::getline(in, text); ++line) {
    if (line == 1 && text.rfind("# expect: ", 0) == 0) e.fragment = text.substr(10, text.find("  # <- error") - 10);
    if (text.find("<- error") != std::string::npos) e.line = line;
  }
  return e;
}

class BadInput : public testing::TestWithParam<std::string> {};

TEST_P(BadInput, IsRejectedNamingFileAndLine) {
  const std::string path = kBad + GetParam() + ".poly";
  const Expectation expected = expectation_of(path);
  ASSERT_FALSE(expected.fragment.empty()) << path << " lacks its '# expect: ' line";
  std::vector<std::string> warnings;
  try {
    validate(read_poly(path), warnings);
    FAIL() << path << " was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), expected.line) << what;
    EXPECT_NE(what.find(expected.fragment), std::string::npos) << what;
    EXPECT_EQ(what.rfind(path, 0), 0u) << "the message starts with the file name: " << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << "one line: " << what;
  }
}

INSTANTIATE_TEST_SUITE_P(CorpusBad, BadInput, testing::ValuesIn(bad_files()),
                         [](const testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

// The loop above is not vacuous: every kind of issue 2 has its file.
TEST(BadInputCorpus, HasAFilePerKind) {
  const std::vector<std::string> names = bad_files();
  for (const char* kind : {"missing-field-vertex", "extra-field-segment", "not-a-number", "nan-coordinate",
                           "infinite-coordinate", "index-out-of-range", "crossing-segments",
                           "collinear-vertices", "too-few-vertices", "lying-header-vertices", "truncated"})
    EXPECT_TRUE(std::find(names.begin(), names.end(), kind) != names.end()) << kind;
}

}  // namespace
}  // namespace lepp
