// SPDX-License-Identifier: GPL-3.0-or-later
// A fixture for the readers' tests: a fresh directory per test (the suite's and the
// test's names, the process id: parallel ctest runs do not meet), removed after it,
// and files written into it byte for byte.
#pragma once
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

namespace lepp {

class ScratchFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("lepp-" + std::string(test->test_suite_name()) + "-" + std::to_string(getpid()) + "-" + test->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  // The file `name` in the test's directory, holding `text`; its path.
  std::string write(const std::string& name, const std::string& text) {
    const std::string path = (dir_ / name).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  std::filesystem::path dir_;
};

}  // namespace lepp
