// SPDX-License-Identifier: GPL-3.0-or-later
// Reading inputs as `lepp refine` does, validating them with the domain
// options, and writing meshes in Triangle's formats.
#include <string>
#include <utility>
#include <vector>

#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "lepp/input.h"
#include "lepp/io.h"
#include "lepp/validate.h"

namespace lepp::python {

void bind_io(py::module_& m) {
  m.def(
      "read_input",
      [](const std::string& path) {
        std::vector<std::string> warnings;
        Pslg p = read_input(path, warnings);
        return std::make_pair(pslg_to_dict(p), warnings);
      },
      py::arg("path"), "A .poly, a .node or a bare prefix, read as lepp refine reads it: (PSLG dict, warnings).");
  m.def(
      "validate",
      [](const py::dict& pslg, bool convex_hull, bool split_crossings) {
        Pslg p = pslg_from_dict(pslg);
        std::vector<std::string> warnings;
        Pslg v;
        {
          py::gil_scoped_release release;
          v = validate(p, DomainOptions{convex_hull, split_crossings}, warnings);
        }
        return std::make_pair(pslg_to_dict(v), warnings);
      },
      py::arg("pslg"), py::arg("convex_hull") = false, py::arg("split_crossings") = false,
      "The PSLG as the engines see it (duplicates merged, ...): (PSLG dict, warnings); InputError when it is not one.");
  m.def(
      "write_triangle",
      [](const std::string& prefix, const py::dict& mesh, const py::list& unimprovable) {
        Mesh m = mesh_from_dict(mesh);
        std::vector<UnimprovableTriangle> bad = unimprovable_from_list(unimprovable);
        py::gil_scoped_release release;
        write_mesh(prefix, m);
        write_unimprovable(prefix, bad);
      },
      py::arg("prefix"), py::arg("mesh"), py::arg("unimprovable") = py::list(),
      "PREFIX.node, PREFIX.ele, PREFIX.poly (and PREFIX.unimprovable) as lepp refine writes them.");
}

}  // namespace lepp::python
