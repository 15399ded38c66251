// SPDX-License-Identifier: GPL-3.0-or-later
// lepp._lepp: the extension under the `lepp` package. lepp.InputError is a
// ValueError carrying the message the CLI prints (file:line: what) and the
// file and line apart; other C++ exceptions become pybind11's usual Python
// ones (std::invalid_argument: ValueError, anything else: RuntimeError), so no
// input reaches the interpreter as a crash.
#include <pybind11/pybind11.h>

#include "bindings.h"
#include "lepp/io.h"
#include "lepp/rounding.h"
#include "lepp/version.h"

namespace py = pybind11;

namespace lepp::python {

void check_signals() {
  if (PyErr_CheckSignals() != 0) throw Interrupted{};
}

}  // namespace lepp::python

PYBIND11_MODULE(_lepp, m) {
  m.doc() = "lepp's C++ libraries (use the lepp package, not this module)";
  static py::exception<lepp::InputError> input_error(m, "InputError", PyExc_ValueError);
  input_error.doc() = "Bad input: the message names the file (or <input>) and line, as lepp's command prints it.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const lepp::InputError& e) {
      // An instance with attributes (py::exception's call operator only sets the message).
      py::object error = py::reinterpret_borrow<py::object>(input_error.ptr())(e.what());
      error.attr("file") = e.file();
      error.attr("line") = e.line();
      PyErr_SetObject(input_error.ptr(), error.ptr());
    } catch (const lepp::python::Interrupted&) {
      // The Python exception is still pending: nothing to set.
      if (!PyErr_Occurred()) PyErr_SetNone(PyExc_KeyboardInterrupt);
    }
  });
  m.attr("__version__") = LEPP_VERSION_STRING;
  // The default bound of the search of tie resolutions (refine, certify, audit: tie_search_states).
  m.attr("TIE_SEARCH_STATES") = lepp::kTieSearchStates;
  lepp::python::bind_io(m);
  lepp::python::bind_refine(m);
  lepp::python::bind_certify(m);
  lepp::python::bind_render(m);
  lepp::python::bind_audit(m);
}
