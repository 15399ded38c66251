// SPDX-License-Identifier: GPL-3.0-or-later
// lepp refine's output (write_refine_files): with more than one thread the
// statistics run beside the writing (joined by the writing thread) and Triangle's .node
// beside its .ele, its lines made during the refinement (stream_node_text); the files,
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

Written refine_and_write(int threads, const std::string& formats, bool stream = false,
                         std::size_t* streamed_lines = nullptr, std::string order = "fifo") {
  RefineRequest request;
  request.input = std::string(LEPP_SOURCE_DIR) + "/corpus/paper/square400.poly";
  request.output = (std::filesystem::temp_directory_path() /
                    ("lepp_refine_files_" + std::to_string(threads) + "_" + std::to_string(::getpid())))
                       .string();
  request.max_area = 0.2;
  request.threads = threads;
  request.formats = {formats};
  request.order = order;
  const RefineInput input = read_refine_input(request);
  RefineOptions options = refine_options(request);
  std::unique_ptr<NodeTextStream> node_text = stream ? stream_node_text(request, options) : nullptr;
  EXPECT_EQ(!!node_text, stream && threads > 1 && formats.find("triangle") != std::string::npos && order != "batch")
      << threads << " threads, " << formats << ", " << order;
  RefineResult result = refine(refine_engine(request), input.pslg, options);
  Written w;
  w.written = write_refine_files(request, result, input.pslg, node_text.get());
  if (node_text && streamed_lines) *streamed_lines = node_text->finish(result.mesh.input_vertices).lines;
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

// lepp refine's .node made beside the refinement (stream_node_text): only where a
// thread is free for it and Triangle's files are asked for; then every line of the
// .node is the stream's, and the files are those of one thread.
TEST(RefineFiles, TheNodeMadeBesideTheRefinementIsTheSame) {
  const Written one = refine_and_write(1, "triangle");
  std::size_t lines = 0;
  const Written two = refine_and_write(2, "triangle", true, &lines);
  EXPECT_TRUE(one.files == two.files) << "the files differ";
  EXPECT_EQ(one.text, two.text);
  EXPECT_EQ(lines, one.written.stats.vertices) << "the .node's lines were not all made beside the refinement";
  EXPECT_GT(lines, 10000u);
  refine_and_write(1, "triangle", true);              // no stream: one thread
  refine_and_write(2, "vtu", true);                   // no stream: no .node
  refine_and_write(2, "triangle", true, nullptr, "batch");  // no stream: the batch order's selection takes the threads
}

}  // namespace
}  // namespace lepp::engines
