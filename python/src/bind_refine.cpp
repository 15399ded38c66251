// SPDX-License-Identifier: GPL-3.0-or-later
// refine: validate and refine as `lepp refine` does, with the GIL released;
// the mesh comes back as arrays owning the engine's vectors. A guard stop
// (Steiner budget, edge floor, time limit) is an outcome, never an exception.
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "lepp/engines/refine_files.h"
#include "lepp/engines/refine_request.h"
#include "lepp/engines/refine_summary.h"
#include "lepp/engines/registry.h"
#include "lepp/input.h"
#include "lepp/io.h"
#include "lepp/mesh_output.h"

namespace lepp::python {
namespace {

// The checks lepp refine's options make (CLI11 ranges and choices), as ValueError.
RefineOptions options_of(const engines::RefineRequest& c) {
  if (!(c.min_angle >= 0 && c.min_angle <= 60)) throw std::invalid_argument("min_angle: must be in [0, 60] degrees");
  if (!(c.max_area >= 0) || std::isinf(c.max_area)) throw std::invalid_argument("max_area: must be a positive number (or None)");
  if (!engines::parse_method(c.method)) throw std::invalid_argument("method: " + engines::quoted_choices(engines::method_names()));
  if (!engines::parse_order(c.order)) throw std::invalid_argument("order: " + engines::quoted_choices(engines::order_names()));
  if (!engines::parse_engine(c.engine, engines::lepp_engines()))
    throw std::invalid_argument("engine: " + engines::quoted_choices(engines::names(engines::lepp_engines())));
  if (c.max_steiner < -1) throw std::invalid_argument("max_steiner: must be >= 0 (or None)");
  if (!(c.time_limit >= 0)) throw std::invalid_argument("time_limit: must be >= 0 seconds (or None)");
  if (c.threads < 0) throw std::invalid_argument("threads: must be >= 0 (0: the machine's cores)");
  return engines::refine_options(c);  // the same options as lepp refine's
}

py::dict run(const py::dict& pslg, const engines::RefineRequest& call) {
  RefineOptions options = options_of(call);
  Pslg raw = pslg_from_dict(pslg);
  // Ctrl-C stops a long run: the engines call this now and then.
  options.on_progress = [](std::int64_t) {
    py::gil_scoped_acquire gil;
    check_signals();
  };
  engines::RefineInput in;  // as lepp refine reads it, less the file
  RefineResult result;
  MeshLabels labels;
  nlohmann::json summary;
  const Pslg& input = in.pslg;
  {
    py::gil_scoped_release release;
    in.pslg = validate(raw, call.domain, in.warnings);
    result = engines::refine(engines::refine_engine(call), input, options);
    // Markers and regions, and the segment ids as lepp refine writes them.
    labels = label_refined_mesh(result.mesh, input, call.domain);
    summary = engines::refine_json_summary(call, in, result);
  }
  py::dict out;
  std::vector<int> edges, edge_segments;
  for (const ConstrainedEdge& e : result.mesh.constrained_edges) {
    edges.insert(edges.end(), {e.a, e.b});
    edge_segments.push_back(e.segment);
  }
  out["edges"] = int_array(edges, 2);
  out["edge_segments"] = int_array(edge_segments);
  out["edge_markers"] = int_array(labels.edge_markers);
  out["triangle_regions"] = int_array(labels.triangle_regions);
  out["region_count"] = labels.region_count;
  out["input_vertices"] = result.mesh.input_vertices;
  out["vertices"] = take_points(std::move(result.mesh.vertices));
  out["triangles"] = take_triangles(std::move(result.mesh.triangles));
  std::vector<int> input_markers = input.vertex_markers;
  out["input_vertex_markers"] = int_array(input_markers);
  py::list unimprovable;
  for (const UnimprovableTriangle& u : result.unimprovable) unimprovable.append(unimprovable_to_dict(u));
  out["unimprovable"] = unimprovable;
  if (call.trace) {
    std::vector<Point> points;
    py::list rules, splits;
    points.reserve(result.trace.size());
    for (const TraceStep& s : result.trace) {
      points.push_back(s.point);
      rules.append(to_string(s.rule));
      splits.append(s.split_segment);
    }
    out["trace"] = take_points(std::move(points));
    out["trace_rules"] = rules;
    out["trace_split_segments"] = splits;
  } else {
    out["trace"] = py::none();
  }
  // The keys of lepp refine --json, less those of its files: the input and output
  // names, and the phases that read and write them.
  summary.erase("input");
  summary.erase("output");
  summary["seconds_by_phase"].erase("read");
  summary["seconds_by_phase"].erase("write");
  out["statistics"] = py::module_::import("json").attr("loads")(summary.dump());
  out["outcome"] = to_string(result.outcome);
  out["converged"] = exit_status(result.outcome) == 0;
  out["warnings"] = in.warnings;
  return out;
}

}  // namespace

void bind_refine(py::module_& m) {
  m.def(
      "refine",
      [](const py::dict& pslg, double min_angle, double max_area, bool region_areas, const std::string& method,
         const std::string& order, const std::string& engine, std::int64_t max_steiner, double edge_floor,
         double time_limit, bool convex_hull, bool split_crossings, bool trace, std::uint64_t order_seed, int threads,
         std::size_t tie_search_states) {
        engines::RefineRequest call;  // lepp refine's request, less its files and printing
        call.min_angle = min_angle, call.max_area = max_area, call.region_areas = region_areas;
        call.method = method, call.order = order, call.engine = engine;
        call.max_steiner = max_steiner, call.edge_floor = edge_floor, call.time_limit = time_limit;
        call.domain.convex_hull = convex_hull, call.domain.split_crossings = split_crossings;
        call.trace = trace, call.order_seed = order_seed, call.threads = threads;
        call.tie_search_states = tie_search_states;
        return run(pslg, call);
      },
      py::arg("pslg"), py::arg("min_angle") = 30.0, py::arg("max_area") = 0.0, py::arg("region_areas") = false,
      py::arg("method") = to_string(Method::Centroid), py::arg("order") = to_string(QueueOrder::Fifo),
      py::arg("engine") = engines::to_string(engines::Engine::Fast), py::arg("max_steiner") = -1,
      py::arg("edge_floor") = -1.0, py::arg("time_limit") = 0.0, py::arg("convex_hull") = false,
      py::arg("split_crossings") = false, py::arg("trace") = false, py::arg("order_seed") = 0, py::arg("threads") = 0,
      py::arg("tie_search_states") = kTieSearchStates,
      "Validate and refine a PSLG dict; a dict of the mesh arrays, statistics and outcome.");
}

}  // namespace lepp::python
