// SPDX-License-Identifier: GPL-3.0-or-later
// The consistent-variant replay (issue 30, item 7): a trace that mixes two
// deviations (the test mesher with --bug area-centroid --bug
// other-second-longest) fits neither variant alone, and fits the two allowed
// together. Kills ref-replay-allows-any-variant and ref-replay-allow-replaces.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "lepp/io.h"
#include "lepp/audit/replay.h"
#include "lepp/trace_io.h"
#include "lepp/validate.h"

namespace fs = std::filesystem;
using lepp::audit::Deviation;
using lepp::audit::Replay;
using lepp::audit::ReplayChoice;
using lepp::audit::ReplayRules;

namespace {

const double kTheta = 25;

lepp::Pslg validated(const std::string& path) {
  std::vector<std::string> warnings;
  return lepp::validate(lepp::read_poly(path), warnings);
}

// The test mesher's trace on a paper input with these seeded bugs.
std::vector<lepp::Point> mesher_trace(const std::string& input, const std::string& bugs) {
  static int run = 0;
  const fs::path dir = fs::temp_directory_path() / ("lepp_variant_mix_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string prefix = (dir / ("run" + std::to_string(run++))).string();
  const std::string cmd = std::string(LEPP_TEST_MESHER) + " " + input + " " + prefix + " " + std::to_string(kTheta) +
                          " centroid " + bugs + " 2>/dev/null";
  const int raw = std::system(cmd.c_str());
  EXPECT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0) << cmd;
  std::vector<lepp::Point> trace = lepp::read_trace(prefix + ".trace");
  fs::remove_all(dir);
  return trace;
}

// How many steps of the trace the replay takes, in order, before one is no
// choice.
std::size_t steps_fitting(Replay& replay, const std::vector<lepp::Point>& trace) {
  for (std::size_t i = 0; i < trace.size(); ++i) {
    ReplayChoice choice;
    if (!replay.match(trace[i], choice)) return i;
    replay.insert(trace[i], choice);
  }
  return trace.size();
}

TEST(VariantMix, TwoDeviationsFitNeitherVariantAlone) {
  std::size_t mixed = 0;
  for (const char* name : {"A.poly", "circles240.poly", "rect162.poly", "square400.poly"}) {
    const std::string input = std::string(LEPP_PAPER_INPUTS) + "/" + name;
    const lepp::Pslg pslg = validated(input);
    const std::vector<lepp::Point> trace = mesher_trace(input, "--bug area-centroid --bug other-second-longest");
    // Both bugs acted on this input (the mesher's own word, not the replay's):
    // the trace is neither bug's alone.
    if (trace == mesher_trace(input, "--bug area-centroid") || trace == mesher_trace(input, "--bug other-second-longest"))
      continue;
    ++mixed;
    ReplayRules rules;
    rules.min_angle_deg = kTheta;
    // Both variants allowed, the second added part way as the conformance check does: every step fits.
    Replay both(pslg, rules);
    both.allow(Deviation::AreaCentroid);
    const std::size_t first = steps_fitting(both, trace);
    both.allow(Deviation::OtherSecondLongest);
    const std::vector<lepp::Point> rest(trace.begin() + static_cast<std::ptrdiff_t>(first), trace.end());
    EXPECT_EQ(steps_fitting(both, rest), rest.size()) << name << ": both variants allowed, from step " << first + 1;
    for (Deviation one : {Deviation::AreaCentroid, Deviation::OtherSecondLongest}) {
      ReplayRules r = rules;
      r.variant = one;
      Replay alone(pslg, r);
      EXPECT_LT(steps_fitting(alone, trace), trace.size())
          << name << ": a trace with both deviations fits " << lepp::audit::to_string(one) << " alone";
    }
  }
  EXPECT_GT(mixed, 0u) << "no paper input gave a trace mixing the two deviations";
}

}  // namespace
