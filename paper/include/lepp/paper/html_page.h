// SPDX-License-Identifier: GPL-3.0-or-later
// docs/paper/index.html: Table 1, the tables per problem and the figures of
// PAPER.md on one self-contained HTML page (lepp::html), written by `lepp paper`.
#pragma once
#include <string>

#include "lepp/paper/options.h"
#include "lepp/paper/study.h"

namespace lepp::paper {

// The page. The figures are read from `figdir` (plots.py's PNGs inlined, Fig. 13's SVG
// drawings inline); one that is not there is named as missing, not drawn.
std::string paper_html(const Options& options, const Study& study, const std::string& figdir, double total_seconds);

}  // namespace lepp::paper
