// SPDX-License-Identifier: GPL-3.0-or-later
// The runs of the study (the paper's Sections 5 and 6) on corpus/paper's four
// problems: ours (centroid, midpoint) at every angle of the list and higher until
// a run does not finish, Lepp-centroid with a lifo queue at 34 to 36 degrees,
// Triangle and CGAL's mesher until a run does not finish; then Triangle and
// Lepp-centroid on each alternative reading at Table 1's angles.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "lepp/paper/options.h"
#include "lepp/paper/readings.h"
#include "lepp/paper/run.h"

namespace lepp::paper {

// What a long study tells as it goes (either may be empty).
struct StudyEvents {
  std::function<void(const std::string&)> note;  // a line for the user: the problem started, a missing tool, a failure
  std::function<void(const Run&)> run;           // each run as it ends
};

struct Study {
  Results results;
  std::vector<double> angles;     // every angle some run was made at, ascending
  std::vector<Reading> readings;  // the readings run (none with --quick)
  std::string engine;             // our engine: fast or reference
  bool triangle_ran = false;      // node and triangle-wasm were there
};

// The angles every method is tried at, ascending (ours go on above them).
const std::vector<double>& study_angles();

// Reads OPTIONS.root/corpus/paper/*.poly (throws lepp::InputError on a bad one)
// and writes the meshes under OPTIONS.work/meshes/, which must exist.
Study run_study(const Options& options, const StudyEvents& events = {});

}  // namespace lepp::paper
