// SPDX-License-Identifier: GPL-3.0-or-later
// lepp refine's output (write_refine_files): with more than one thread the
// statistics run beside the writing and Triangle's .node beside its .ele; the files,
// the statistics and the printed summary are those of one thread. Run under
// ThreadSanitizer in CI (scripts/ci.d/15-threads-tsan.sh).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <unistd.h>

#include "lepp/engines/refine_files.h"
#include "lepp/engines/refine_summary.h"
#include "lepp/engines/registry.h"

namespace lepp::engines {
namespace {

std::string bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct Written {
  std::string files, text;
  RefineWritten written;
};

Written refine_and_write(int threads, const std::string& formats) {
  RefineRequest request;
  request.input = std::string(LEPP_SOURCE_DIR) + "/corpus/paper/square400.poly";
  request.output = (std::filesystem::temp_directory_path() /
                    ("lepp_refine_files_" + std::to_string(threads) + "_" + std::to_string(::getpid())))
                       .string();
  request.max_area = 0.2;
  request.threads = threads;
  request.formats = {formats};
  const RefineInput input = read_refine_input(request);
  RefineResult result = refine(refine_engine(request), input.pslg, refine_options(request));
  Written w;
  w.written = write_refine_files(request, result, input.pslg);
  for (const char* ext : {".node", ".ele", ".poly", ".vtu"}) {
    w.files += bytes(request.output + ext);
    std::filesystem::remove(request.output + ext);
  }
  std::filesystem::remove(request.output + ".unimprovable");
  w.text = refine_text_summary(request, input, result, w.written);
  w.text.erase(w.text.find("seconds "));  // the last line: the only one that differs
  return w;
}

TEST(RefineFiles, OutputThreadsChangeNothingButTheTime) {
  for (const char* formats : {"triangle", "vtu"}) {
    const Written one = refine_and_write(1, formats), two = refine_and_write(2, formats);
    EXPECT_GT(one.files.size(), 10000u) << formats;
    EXPECT_TRUE(one.files == two.files) << formats << ": the files differ";
    EXPECT_EQ(one.text, two.text) << formats;
    EXPECT_EQ(one.written.stats.triangles, two.written.stats.triangles);
    EXPECT_EQ(one.written.stats.min_angle_deg, two.written.stats.min_angle_deg);
    EXPECT_EQ(one.written.stats.avg_min_angle_deg, two.written.stats.avg_min_angle_deg);
    EXPECT_GT(two.written.write_seconds, 0.0);
    EXPECT_GT(two.written.statistics_seconds, 0.0);
  }
}

}  // namespace
}  // namespace lepp::engines
