// SPDX-License-Identifier: GPL-3.0-or-later
// Each part of the extension module registers its functions here (module.cpp calls them).
#pragma once
#include <pybind11/pybind11.h>

namespace lepp::python {

void bind_io(pybind11::module_& m);
void bind_refine(pybind11::module_& m);
void bind_certify(pybind11::module_& m);
void bind_render(pybind11::module_& m);
void bind_audit(pybind11::module_& m);

// A KeyboardInterrupt (or another pending signal's exception) seen while the
// GIL was released: thrown through the engines, which catch only
// std::exception, and turned back into the Python exception by the module.
struct Interrupted {};

// With the GIL held: throws Interrupted when a signal handler raised.
void check_signals();

}  // namespace lepp::python
