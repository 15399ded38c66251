// SPDX-License-Identifier: GPL-3.0-or-later
// certify: the exact certifier on a PSLG dict and a mesh dict; the report is
// `lepp certify --json`'s, as Python objects, with its text beside it.
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "lepp/certify.h"
#include "lepp/certify_html.h"
#include "lepp/certify_json.h"
#include "lepp/input.h"

namespace lepp::python {
namespace {

// The certifier's options from the keyword arguments both functions below take.
certify::Options options_of(double min_angle, bool conforming, bool theorem2, bool exempt_small_input_angles, double max_area,
                            bool region_areas, std::size_t max_listed, const py::list& unimprovable,
                            std::size_t tie_search_states, double time_limit) {
  if (!(min_angle >= 0 && min_angle <= 60)) throw std::invalid_argument("min_angle: must be in [0, 60] degrees");
  if (!(max_area >= 0)) throw std::invalid_argument("max_area: must be >= 0 (or None)");
  if (!(time_limit >= 0)) throw std::invalid_argument("time_limit: must be >= 0 seconds (or None)");
  certify::Options o;
  o.min_angle_deg = min_angle;
  o.conforming = conforming;
  o.theorem2 = theorem2;
  o.exempt_small_input_angles = exempt_small_input_angles;
  o.max_area = max_area;
  o.region_area_bounds = region_areas;
  o.max_listed_per_reason = max_listed;
  o.unimprovable = unimprovable_from_list(unimprovable);
  o.tie_search_states = tie_search_states;
  o.time_limit_seconds = time_limit;
  return o;
}

}  // namespace

void bind_certify(py::module_& m) {
  m.def(
      "certify",
      [](const py::dict& pslg, const py::dict& mesh, double min_angle, bool conforming, bool theorem2,
         bool exempt_small_input_angles, double max_area, bool region_areas, std::size_t max_listed, bool convex_hull,
         bool split_crossings, const py::list& unimprovable, std::size_t tie_search_states, double time_limit, int threads) {
        if (threads < 0) throw std::invalid_argument("threads: must be >= 0 (0: the machine's cores)");
        certify::Options o = options_of(min_angle, conforming, theorem2, exempt_small_input_angles, max_area, region_areas,
                                              max_listed, unimprovable, tie_search_states, time_limit);
        o.threads = threads;
        Pslg raw = pslg_from_dict(pslg);
        Mesh m = mesh_from_dict(mesh);
        std::vector<std::string> warnings;
        std::string json, text;
        {
          py::gil_scoped_release release;
          const Pslg input = validate(raw, DomainOptions{convex_hull, split_crossings}, warnings);
          const certify::Report report = certify::certify(input, m, o);
          json = certify::json_report(report, max_listed).dump();
          text = certify::format_report(report);
        }
        py::object report = py::module_::import("json").attr("loads")(json);
        return py::make_tuple(report, text, warnings);
      },
      py::arg("pslg"), py::arg("mesh"), py::arg("min_angle") = 0.0, py::arg("conforming") = false,
      py::arg("theorem2") = true, py::arg("exempt_small_input_angles") = false, py::arg("max_area") = 0.0,
      py::arg("region_areas") = false, py::arg("max_listed") = 50, py::arg("convex_hull") = false,
      py::arg("split_crossings") = false, py::arg("unimprovable") = py::list(),
      py::arg("tie_search_states") = kTieSearchStates, py::arg("time_limit") = 0.0, py::arg("threads") = 1,
      "The exact certificate: (report dict as lepp certify --json, report text, warnings).");
  m.def(
      "certify_html",
      [](const py::dict& pslg, const py::dict& mesh, double min_angle, bool conforming, bool theorem2,
         bool exempt_small_input_angles, double max_area, bool region_areas, std::size_t max_listed, bool convex_hull,
         bool split_crossings, const py::list& unimprovable, std::size_t tie_search_states, double time_limit,
         const std::string& title) {
        const certify::Options o = options_of(min_angle, conforming, theorem2, exempt_small_input_angles, max_area, region_areas,
                                              max_listed, unimprovable, tie_search_states, time_limit);
        Pslg raw = pslg_from_dict(pslg);
        Mesh m = mesh_from_dict(mesh);
        std::vector<std::string> warnings;
        py::gil_scoped_release release;
        const Pslg input = validate(raw, DomainOptions{convex_hull, split_crossings}, warnings);
        certify::HtmlOptions h;
        h.title = title;
        return certify::html_report(m, certify::certify(input, m, o), h);
      },
      py::arg("pslg"), py::arg("mesh"), py::arg("min_angle") = 0.0, py::arg("conforming") = false,
      py::arg("theorem2") = true, py::arg("exempt_small_input_angles") = false, py::arg("max_area") = 0.0,
      py::arg("region_areas") = false, py::arg("max_listed") = 50, py::arg("convex_hull") = false,
      py::arg("split_crossings") = false, py::arg("unimprovable") = py::list(),
      py::arg("tie_search_states") = kTieSearchStates, py::arg("time_limit") = 0.0, py::arg("title") = "",
      "The certificate as lepp certify --html writes it: one self-contained HTML page.");
  m.def(
      "certify_checks",
      [] {
        // Every reason with the check it belongs to, in the certifier's order.
        std::vector<std::pair<std::string, std::string>> out;
        for (int r = 0; r <= static_cast<int>(certify::Reason::AreaAboveBound); ++r) {
          const auto reason = static_cast<certify::Reason>(r);
          out.emplace_back(certify::to_string(reason), certify::to_string(certify::check_of(reason)));
        }
        return out;
      },
      "[(reason, check)] for every reason a check can fail with.");
}

}  // namespace lepp::python
