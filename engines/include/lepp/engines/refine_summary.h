// SPDX-License-Identifier: GPL-3.0-or-later
// What `lepp refine` prints of a run: its statistics as JSON (--json) or as text.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "lepp/engines/refine_files.h"
#include "lepp/engines/refine_request.h"
#include "lepp/refine.h"

namespace lepp::engines {

// `lepp refine --json`'s object (docs/FORMATS.md), "lepp_version" included. `result`
// is the run of `request` on `input`, its mesh labelled (label_refined_mesh).
// `write_seconds`: what label_and_write_refine_outputs returned (null in the
// phases when negative); the statistics phase is this function's own.
nlohmann::json refine_json_summary(const RefineRequest& request, const RefineInput& input, const RefineResult& result,
                                   double write_seconds = -1);

// `lepp refine`'s text: one "name  value" line per statistic, each ending in '\n'.
std::string refine_text_summary(const RefineRequest& request, const RefineInput& input, const RefineResult& result);

}  // namespace lepp::engines
