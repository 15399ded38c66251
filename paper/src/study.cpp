// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind lepp/paper/study.h: the runs of the study (the paper's Sections 5 and
// 6) on corpus/paper's four problems.
#include "lepp/paper/study.h"

#include <algorithm>
#include <filesystem>

#include "lepp/io.h"
#include "lepp/paper/numbers.h"
#include "lepp/paper/runner.h"
#include "lepp/validate.h"
#include "mesher_names.h"

namespace fs = std::filesystem;

namespace lepp::paper {
namespace {

Pslg load(const std::string& path) {
  std::vector<std::string> warnings;
  return validate(read_poly(path), warnings);
}

}  // namespace

const std::vector<double>& study_angles() {
  static const std::vector<double> angles = {10, 15, 20, 25, 28, 30, 32, 34, 35, 36};
  return angles;
}

Study run_study(const Options& options, const StudyEvents& events) {
  auto note = [&](const std::string& line) {
    if (events.note) events.note(line);
  };
  Study study;
  auto record = [&](const Run& r) {
    if (events.run) events.run(r);
    study.results.add(r);
  };
  const fs::path corpus = fs::path(options.root) / "corpus" / "paper";
  const std::vector<double>& angles = study_angles();
  const double max_theta = options.quick ? 36 : 45;
  Runner runner(options);
  study.triangle_ran = runner.triangle_available();
  if (!study.triangle_ran) note("node or triangle-wasm missing: Triangle's column is left empty");

  study.angles = angles;
  for (const auto& p : paper_problems()) {
    std::string poly = (corpus / (p.key + ".poly")).string();
    Pslg pslg = load(poly);
    note(p.name);
    // Ours: every angle of the list, then higher until a run does not finish;
    // after a run that does not finish, higher angles are not tried.
    for (const std::string method : {centroid_name(), midpoint_name()}) {
      bool failed = false;
      for (double theta = angles.front(); theta <= max_theta && !failed;) {
        Run r = runner.lepp_run(p.key, "", pslg, method, theta);
        failed = !r.finished;
        record(r);
        if (std::find(study.angles.begin(), study.angles.end(), theta) == study.angles.end()) study.angles.push_back(theta);
        auto next = std::upper_bound(angles.begin(), angles.end(), theta);
        theta = next != angles.end() ? *next : theta + 1;
      }
    }
    // Queue-order sensitivity at the top of the range.
    for (double theta : {34.0, 35.0, 36.0}) record(runner.lepp_run(p.key, "", pslg, centroid_name(), theta, lifo_name()));
    if (study.triangle_ran) {
      for (double theta : angles) {
        Run r = runner.triangle_run(p.key, "", poly, pslg, theta);
        record(r);
        if (!r.finished) break;
      }
    }
    for (double theta : angles) {
      Run r = runner.cgal_run(p.key, "", pslg, theta);
      record(r);
      if (!r.finished) break;
    }
  }
  std::sort(study.angles.begin(), study.angles.end());

  // Readings of the two problems whose geometry the paper does not pin down.
  if (!options.quick) study.readings = find_readings(options.root);
  for (const auto& rd : study.readings) {
    Pslg pslg = load(rd.path);
    note("reading " + rd.stem);
    for (int theta : table_angles()) {
      if (study.triangle_ran) record(runner.triangle_run(rd.problem, rd.stem, rd.path, pslg, theta));
      record(runner.lepp_run(rd.problem, rd.stem, pslg, centroid_name(), theta));
    }
  }
  study.engine = runner.engine();
  return study;
}

}  // namespace lepp::paper
