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
// is the run of `request` on `input`, its mesh labelled (label_refined_mesh), and
// `written` what write_refine_files returned for it.
nlohmann::json refine_json_summary(const RefineRequest& request, const RefineInput& input, const RefineResult& result,
                                   const RefineWritten& written);
// The same with no files written (Python's statistics): the statistics computed
// here, the "write" phase null.
nlohmann::json refine_json_summary(const RefineRequest& request, const RefineInput& input, const RefineResult& result);

// `lepp refine`'s text: one "name  value" line per statistic, each ending in '\n'.
std::string refine_text_summary(const RefineRequest& request, const RefineInput& input, const RefineResult& result,
                                const RefineWritten& written);

}  // namespace lepp::engines
