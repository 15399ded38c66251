// SPDX-License-Identifier: GPL-3.0-or-later
// Benchmark inputs: the paper's corpus and generated problems of a chosen output size.
#pragma once
#include <string>
#include <vector>

#include "lepp/pslg.h"
#include "lepp/refine.h"

namespace lepp::bench {

struct Problem {
  std::string name;
  Pslg pslg;           // validated
  double theta = 30;
  double max_area = 0;  // 0: none
};

// The options that refine a problem: its theta and its size bound.
RefineOptions refine_options(const Problem& p);

// The paper's four problems (corpus/paper) at theta.
std::vector<Problem> paper_problems(const std::string& corpus_dir, double theta);

// The unit square with boundary vertices spaced for about `triangles` output
// triangles and the size bound that gives them (about 1.4 / max_area triangles).
Problem square_with_size_bound(double triangles);

// `count` random points (fixed seed) inside the unit square with a boundary of 4 x 64 vertices, no size bound.
Problem random_points(int count);

}  // namespace lepp::bench
