// SPDX-License-Identifier: GPL-3.0-or-later
// The replay driver: a fuzz target's source compiled with g++ and this main()
// instead of libFuzzer's, so ctest replays the corpus in the default build.
//   <target>_replay [--expect-finding | --as-fuzzer] PATH...
// Each file (directories: every file directly in them, sorted; .md skipped) is fed once to
// LLVMFuzzerTestOneInput. Without --expect-finding a reported finding fails the
// run; with it, every file must still report one (known-open findings: when an
// engine fix makes one pass, move its file out of open/). With --as-fuzzer,
// findings behave as under libFuzzer: a finding aborts, a known loop outside
// the paper's claims is kept (LEPP_FUZZ_KNOWN_DIR) and the replay goes on.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "support/finding.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

// The custom mutators call libFuzzer's mutator; never called when replaying.
extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t*, std::size_t size, std::size_t) { return size; }

namespace fs = std::filesystem;

int main(int argc, char** argv) {
  bool expect = false, as_fuzzer = false;
  std::vector<fs::path> files;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--expect-finding") {
      expect = true;
    } else if (arg == "--as-fuzzer") {
      as_fuzzer = true;
    } else if (fs::is_directory(arg)) {
      for (const auto& entry : fs::directory_iterator(arg))  // not recursive: open/ is replayed apart
        if (entry.is_regular_file() && entry.path().extension() != ".md") files.push_back(entry.path());
    } else if (fs::exists(arg)) {
      files.emplace_back(arg);
    } else {
      std::fprintf(stderr, "no such file or directory: %s\n", arg.c_str());
      return 2;
    }
  }
  std::sort(files.begin(), files.end());
  lepp::fuzz::set_expect_findings(!as_fuzzer);
  int failures = 0;
  for (const fs::path& file : files) {
    std::ifstream in(file, std::ios::binary);
    const std::vector<char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    bool found = false;
    try {
      LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    } catch (const lepp::fuzz::FindingReported&) {
      found = true;
    }
    if (found != expect) {
      ++failures;
      std::fprintf(stderr, "FAIL %s: %s\n", file.c_str(), expect ? "no longer reports its finding (fixed? move it)" : "reports a finding");
    }
  }
  std::printf("replayed %zu inputs, %d failures\n", files.size(), failures);
  return failures ? 1 : 0;
}
