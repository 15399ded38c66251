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
#include <set>
#include <string>
#include <vector>

#include "lepp/io.h"
#include "lepp/reference_replay.h"
#include "lepp/trace_io.h"
#include "lepp/validate.h"

namespace fs = std::filesystem;
using lepp::reference::Deviation;
using lepp::reference::Replay;
using lepp::reference::ReplayChoice;
using lepp::reference::ReplayRules;

namespace {

const double kTheta = 25;

lepp::Pslg validated(const std::string& path) {
  std::vector<std::string> warnings;
  return lepp::validate(lepp::read_poly(path), warnings);
}

// The test mesher's trace on a paper input with both bugs.
std::vector<lepp::Point> mixed_trace(const std::string& input) {
  const fs::path dir = fs::temp_directory_path() / ("lepp_variant_mix_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string prefix = (dir / fs::path(input).stem()).string();
  const std::string cmd = std::string(LEPP_TEST_MESHER) + " " + input + " " + prefix + " " + std::to_string(kTheta) +
                          " centroid --bug area-centroid --bug other-second-longest 2>/dev/null";
  const int raw = std::system(cmd.c_str());
  EXPECT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0) << cmd;
  std::vector<lepp::Point> trace = lepp::read_trace(prefix + ".trace");
  fs::remove_all(dir);
  return trace;
}

// How many steps of the trace the replay takes, in order, before one is no
// choice; each taken step's variant (Unknown: the paper's choice) in `named`.
std::size_t steps_fitting(Replay& replay, const std::vector<lepp::Point>& trace, std::set<Deviation>* named = nullptr) {
  for (std::size_t i = 0; i < trace.size(); ++i) {
    ReplayChoice choice;
    if (!replay.match(trace[i], choice)) return i;
    if (named) named->insert(choice.deviation);
    replay.insert(trace[i], choice);
  }
  return trace.size();
}

TEST(VariantMix, TwoDeviationsFitNeitherVariantAlone) {
  std::size_t mixed = 0;
  for (const char* name : {"A.poly", "circles240.poly", "rect162.poly", "square400.poly"}) {
    const std::string input = std::string(LEPP_PAPER_INPUTS) + "/" + name;
    const lepp::Pslg pslg = validated(input);
    const std::vector<lepp::Point> trace = mixed_trace(input);
    ReplayRules rules;
    rules.min_angle_deg = kTheta;
    // Both variants allowed, the second added part way as the conformance check
    // does: every step fits, and the steps show both, or this input is not the case.
    Replay both(pslg, rules);
    both.allow(Deviation::AreaCentroid);
    std::set<Deviation> named;
    const std::size_t first = steps_fitting(both, trace, &named);
    both.allow(Deviation::OtherSecondLongest);
    std::vector<lepp::Point> rest(trace.begin() + static_cast<std::ptrdiff_t>(first), trace.end());
    if (steps_fitting(both, rest, &named) < rest.size()) continue;
    if (!named.count(Deviation::AreaCentroid) || !named.count(Deviation::OtherSecondLongest)) continue;
    ++mixed;
    for (Deviation one : {Deviation::AreaCentroid, Deviation::OtherSecondLongest}) {
      ReplayRules r = rules;
      r.variant = one;
      Replay alone(pslg, r);
      EXPECT_LT(steps_fitting(alone, trace), trace.size())
          << name << ": a trace with both deviations fits " << lepp::reference::to_string(one) << " alone";
    }
  }
  EXPECT_GT(mixed, 0u) << "no paper input gave a trace mixing the two deviations";
}

}  // namespace
