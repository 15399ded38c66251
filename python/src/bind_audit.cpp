// SPDX-License-Identifier: GPL-3.0-or-later
// audit: a Python callable as a lepp::audit::Engine (lepp/audit/engine.h), run
// by the same loop as `lepp audit` (rows, shrinking, findings on disk, the
// reports). The audit runs with the GIL released; the adapter takes it back
// for each call. The callable is lepp/_audit.py's wrapper around the user's
// function: it returns a plain mesh dict or raises.
#include <chrono>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "lepp/audit/audit.h"
#include "lepp/audit/inputs/data_root.h"
#include "lepp/audit/report/html.h"
#include "lepp/audit/report/report.h"
#include "lepp/engines/builtin_engines.h"
#include "lepp/engines/registry.h"

namespace lepp::python {
namespace {

using Clock = std::chrono::steady_clock;

// The Python error as one line: "TypeError: ...", and its traceback's text in stderr_text.
void describe(const py::error_already_set& e, audit::EngineRun& run) {
  run.detail = std::string("Python exception: ") + e.what();
  const auto newline = run.detail.find('\n');
  if (newline != std::string::npos) run.detail.resize(newline);
  try {
    py::object format = py::module_::import("traceback").attr("format_exception");
    for (const py::handle line : format(e.type(), e.value(), e.trace())) run.stderr_text += line.cast<std::string>();
  } catch (const py::error_already_set&) {
  }
}

audit::Engine python_engine(py::object callable) {
  // The object is released with the GIL held (the Engine may be destroyed without it).
  auto holder = std::shared_ptr<py::object>(new py::object(std::move(callable)), [](py::object* o) {
    py::gil_scoped_acquire gil;
    delete o;
  });
  return [holder](const Pslg& pslg, const audit::EngineRequest& request) {
    audit::EngineRun run;
    const auto t0 = Clock::now();
    py::gil_scoped_acquire gil;
    try {
      py::object out = (*holder)(pslg_to_dict(pslg), request.theta, to_string(request.method), request.work_dir);
      const py::dict d = out.cast<py::dict>();
      if (d.contains("stopped") && !d["stopped"].is_none()) {
        run.status = audit::RunStatus::Stopped;
        run.detail = "stopped: " + py::str(d["stopped"]).cast<std::string>();
      }
      run.mesh = mesh_from_dict(d);
      if (d.contains("trace") && !d["trace"].is_none()) {
        const auto trace = d["trace"].cast<py::array_t<double, py::array::c_style | py::array::forcecast>>();
        std::vector<Point> points;
        for (py::ssize_t i = 0; i + 1 < trace.size(); i += 2) points.push_back({trace.data()[i], trace.data()[i + 1]});
        run.trace = std::move(points);
      }
    } catch (py::error_already_set& e) {
      if (e.matches(PyExc_KeyboardInterrupt)) {
        e.restore();  // pending again: the module re-raises it
        throw Interrupted{};
      }
      run = audit::EngineRun{};
      run.status = audit::RunStatus::Crashed;
      describe(e, run);
    } catch (const std::exception& e) {
      run = audit::EngineRun{};
      run.status = audit::RunStatus::Crashed;
      run.detail = std::string("bad mesh from the engine: ") + e.what();
    }
    check_signals();
    run.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    // In process, nothing can kill it: a run that came back after the timeout counts as one that did not.
    if (request.timeout_seconds > 0 && run.seconds > request.timeout_seconds && run.status == audit::RunStatus::Ok) {
      run.status = audit::RunStatus::TimedOut;
      run.detail = "returned after the timeout (" + std::to_string(request.timeout_seconds) + " s)";
    }
    return run;
  };
}

struct AuditCall {
  std::string name;
  std::string method;
  std::vector<double> thetas;
  std::size_t cases;
  std::uint64_t seed;
  std::vector<std::string> sources, inputs, compare;
  std::string root, out, junit;
  double timeout;
  double angle_tolerance, point_tolerance;
  bool shrink;
  std::size_t max_findings;
  double shrink_seconds;
  std::size_t tie_search_states;
};

py::tuple run(py::object engine, const AuditCall& c) {
  audit::AuditOptions o;
  const std::optional<Method> method = engines::parse_method(c.method);
  if (!method) throw std::invalid_argument("method: " + engines::quoted_choices(engines::method_names()));
  o.engine_name = c.name;
  o.method = *method;
  o.thetas = c.thetas;
  o.cases = c.cases;
  o.inputs.seed = c.seed;
  o.inputs.dirs = c.inputs;
  // Empty: share/lepp beside the executable, else the source tree, as `lepp audit` (data_root.h).
  o.inputs.source_root = audit::find_data_root(c.root);
  o.inputs.generated = o.inputs.paper = o.inputs.corpus = false;
  for (const std::string& s : c.sources) {
    if (s == "gen") o.inputs.generated = true;
    else if (s == "paper") o.inputs.paper = true;
    else if (s == "corpus") o.inputs.corpus = true;
    else throw std::invalid_argument("sources: unknown source " + s + " (gen, paper, corpus)");
  }
  // In process only: lepp's own engines among the comparisons, in their order.
  std::vector<engines::Engine> comparisons;
  std::string choices;
  for (engines::Engine e : engines::comparison_engines())
    if (engines::is_lepp_engine(e)) {
      comparisons.push_back(e);
      choices += (choices.empty() ? "" : ", ") + std::string(engines::to_string(e));
    }
  for (const std::string& e : c.compare) {
    const std::optional<engines::Engine> which = engines::parse_engine(e, comparisons);
    if (!which) throw std::invalid_argument("compare: unknown engine " + e + " (" + choices + ")");
    o.comparisons.push_back({engines::comparison_title(*which), engines::lepp_audit_engine(*which, QueueOrder::Fifo, c.tie_search_states)});
  }
  o.timeout_seconds = c.timeout;
  o.checks.angle_tolerance_deg = c.angle_tolerance;
  o.checks.point_tolerance_ulps = c.point_tolerance;
  o.checks.tie_search_states = c.tie_search_states;
  o.out_dir = c.out;
  o.shrink = c.shrink;
  o.max_findings_per_row = c.max_findings;
  o.shrink_max_seconds = c.shrink_seconds;
  audit::Engine adapted = python_engine(std::move(engine));
  std::string json, markdown, page;
  int status = 0;
  {
    py::gil_scoped_release release;
    try {
      const audit::AuditReport report = audit::run_audit(adapted, o);
      json = audit::json_report(report).dump();
      markdown = audit::markdown_report(report);
      page = audit::html_report(report);  // now, while the findings' pictures are on disk
      status = audit::exit_status(report);
      if (!c.junit.empty()) {
        std::ofstream junit(c.junit);
        junit << audit::junit_report(report);
        if (!junit) throw std::runtime_error("cannot write " + c.junit);
      }
    } catch (const audit::UsageError& e) {
      throw std::invalid_argument(e.what());
    }
  }
  return py::make_tuple(py::module_::import("json").attr("loads")(json), markdown, status, page);
}

}  // namespace

void bind_audit(py::module_& m) {
  m.def(
      "audit",
      [](py::object engine, const std::string& name, const std::string& method, const std::vector<double>& thetas,
         std::size_t cases, std::uint64_t seed, const std::vector<std::string>& sources,
         const std::vector<std::string>& inputs, const std::vector<std::string>& compare, const std::string& root,
         const std::string& out, const std::string& junit, double timeout, double angle_tolerance,
         double point_tolerance, bool shrink, std::size_t max_findings, double shrink_seconds,
         std::size_t tie_search_states) {
        return run(std::move(engine), AuditCall{name, method, thetas, cases, seed, sources, inputs, compare, root, out,
                                                junit, timeout, angle_tolerance, point_tolerance, shrink, max_findings,
                                                shrink_seconds, tie_search_states});
      },
      py::arg("engine"), py::arg("name"), py::arg("method"), py::arg("thetas"), py::arg("cases"), py::arg("seed"),
      py::arg("sources"), py::arg("inputs"), py::arg("compare"), py::arg("root"), py::arg("out"), py::arg("junit"),
      py::arg("timeout"), py::arg("angle_tolerance"), py::arg("point_tolerance"), py::arg("shrink"),
      py::arg("max_findings"), py::arg("shrink_seconds"), py::arg("tie_search_states"),
      "lepp audit of a Python engine(pslg, theta, method, work_dir) -> mesh dict: (JSON report, markdown, exit status).");
}

}  // namespace lepp::python
