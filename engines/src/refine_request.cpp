// SPDX-License-Identifier: GPL-3.0-or-later
// `lepp refine`'s request checked before anything is read, and turned into RefineOptions.
#include "lepp/engines/refine_request.h"

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "lepp/mesh_output.h"

namespace lepp::engines {
namespace {

// The input file that an output file of prefix `output` would overwrite, or ""
// (`lepp refine X.poly -o X` would write X.poly over the file being read; the
// files read: the path, a bare prefix's X.poly and X.node, a .poly's X.node).
std::string input_overwritten(const std::string& input, const std::string& output) {
  namespace fs = std::filesystem;
  std::vector<std::string> read = {input, input + ".poly", input + ".node"};
  if (fs::path(input).extension() == ".poly") read.push_back(fs::path(input).replace_extension(".node").string());
  for (const std::string& r : read)
    for (const char* ext : {".node", ".ele", ".poly", ".vtu", ".msh", ".unimprovable", ".trace"}) {
      std::error_code ec;
      if (fs::equivalent(output + ext, r, ec)) return r;
    }
  return "";
}

template <class T>
T named(const std::optional<T>& value, const char* what, const std::string& name) {
  if (!value) throw std::invalid_argument(std::string("lepp refine: unknown ") + what + " " + name);
  return *value;
}

}  // namespace

std::string refine_request_error(const RefineRequest& request) {
  if (const std::string overwritten = input_overwritten(request.input, request.output); !overwritten.empty())
    return "-o " + request.output + " would write over the input " + overwritten +
           "; give another output prefix (Triangle writes " + request.output + ".1.*)";
  // A format name that is none is the option parser's to refuse (CLI11 checks the names).
  if (choose_mesh_formats(request.formats).same_file)
    return "--format msh2 and --format msh4 would both write " + request.output + ".msh; ask for one per run";
  return "";
}

RefineOptions refine_options(const RefineRequest& request) {
  RefineOptions options;
  options.min_angle_deg = request.min_angle;
  options.method = named(parse_method(request.method), "method", request.method);
  options.order = named(parse_order(request.order), "order", request.order);
  options.order_seed = request.order_seed;
  options.threads = request.threads;
  options.max_steiner = request.max_steiner;
  options.max_area = request.max_area;
  options.region_area_bounds = request.region_areas;
  options.time_limit_seconds = request.time_limit;
  options.edge_floor = request.edge_floor;
  options.tie_search_states = request.tie_search_states;
  options.trace = request.trace;
  return options;
}

Engine refine_engine(const RefineRequest& request) {
  return named(parse_engine(request.engine, lepp_engines()), "engine", request.engine);
}

}  // namespace lepp::engines
