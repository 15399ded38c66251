// SPDX-License-Identifier: GPL-3.0-or-later
// Reading inputs as `lepp refine` does, validating them with the domain
// options, and writing meshes in every format lepp refine --format writes.
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "lepp/input.h"
#include "lepp/io.h"
#include "lepp/mesh_output.h"
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
      "write_mesh",
      [](const std::string& prefix, const py::dict& mesh, const std::vector<std::string>& formats, bool binary,
         const py::list& unimprovable) {
        const MeshFormatChoice choice = choose_mesh_formats(formats);
        if (choice.unknown)
          throw std::invalid_argument("format: '" + *choice.unknown + "' is none of triangle, vtu, msh2, msh4");
        if (choice.same_file)
          throw std::invalid_argument("format: msh2 and msh4 would both write " + prefix + ".msh; ask for one per call");
        Mesh m = mesh_from_dict(mesh);
        const MeshLabels labels = labels_from_dict(mesh, m);
        std::vector<UnimprovableTriangle> bad = unimprovable_from_list(unimprovable);
        MeshWriteOptions options;
        options.binary = binary;
        py::gil_scoped_release release;
        try {
          write_refined_mesh(prefix, m, labels, bad, choice.formats, options);
        } catch (const std::system_error& e) {
          throw InputError(prefix, 0, std::string("cannot write mesh: ") + e.what());
        }
      },
      py::arg("prefix"), py::arg("mesh"), py::arg("formats"), py::arg("binary") = false,
      py::arg("unimprovable") = py::list(),
      "PREFIX.node/.ele/.poly, PREFIX.vtu, PREFIX.msh (and PREFIX.unimprovable) as lepp refine --format writes them.");
}

}  // namespace lepp::python
