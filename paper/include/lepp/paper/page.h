// SPDX-License-Identifier: GPL-3.0-or-later
// docs/PAPER.md: Table 1 beside the paper's, every method per problem, Fig. 12's
// caption, the distance to the paper's columns, the readings, the claims, why
// the numbers differ, the queue order, and the figures.
#pragma once
#include <string>

#include "lepp/paper/options.h"
#include "lepp/paper/study.h"

namespace lepp::paper {

// The page (markdown). plots_ok: the matplotlib figures exist (or were not asked
// for); total_seconds: the whole reproduction's time, printed on the page.
std::string paper_page(const Options& options, const Study& study, bool plots_ok, double total_seconds);

}  // namespace lepp::paper
