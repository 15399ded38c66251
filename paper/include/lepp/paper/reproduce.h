// SPDX-License-Identifier: GPL-3.0-or-later
// The paper reproduction (`lepp paper`): the study's runs, then
// OUT/paper/results.json, the figures, and OUT/PAPER.md.
#pragma once
#include <string>

#include "lepp/paper/options.h"
#include "lepp/paper/study.h"

namespace lepp::paper {

struct Reproduction {
  int status = 0;      // 0 page written (runs that did not finish are reported on it); 2 corpus not found
  std::string error;   // why not, when status != 0
  Study study;
  std::string figdir;  // OUT/paper: results.json and the figures
  double seconds = 0;  // the whole reproduction
};

// Runs the study and writes its files; `events` hear about each run, the
// problems as they start, and what failed on the way (plots, drawings).
Reproduction reproduce(const Options& options, const StudyEvents& events = {});

}  // namespace lepp::paper
