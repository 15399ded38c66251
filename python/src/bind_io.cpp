// SPDX-License-Identifier: GPL-3.0-or-later
// Reading inputs as `lepp refine` does, validating them with the domain
// options, writing meshes in every format lepp refine --format writes, and the
// .vtu's per-triangle measures as arrays (Mesh.to_meshio, lepp.plot).
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "lepp/input.h"
#include "lepp/io.h"
#include "lepp/mesh_formats.h"
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
  m.def(
      "triangle_measures",
      [](const py::dict& mesh) {
        const Mesh m = mesh_from_dict(mesh);
        for (const Tri& tri : m.triangles)
          for (int v : tri)
            if (v < 0 || static_cast<std::size_t>(v) >= m.vertices.size())
              throw std::invalid_argument("triangles: vertex id " + std::to_string(v) + " out of range");
        const auto& measures = triangle_measures();
        const auto count = static_cast<py::ssize_t>(m.triangles.size());
        std::vector<py::array_t<double>> arrays;
        std::vector<double*> data;
        for (std::size_t k = 0; k < measures.size(); ++k) {
          arrays.emplace_back(count);
          data.push_back(arrays.back().mutable_data());
        }
        {
          py::gil_scoped_release release;
          for (std::size_t t = 0; t < m.triangles.size(); ++t) {
            const Tri& tri = m.triangles[t];
            const Point& a = m.vertices[static_cast<std::size_t>(tri[0])];
            const Point& b = m.vertices[static_cast<std::size_t>(tri[1])];
            const Point& c = m.vertices[static_cast<std::size_t>(tri[2])];
            for (std::size_t k = 0; k < measures.size(); ++k) data[k][t] = measures[k].of(a, b, c);
          }
        }
        py::dict out;  // in the .vtu's order (dicts keep it)
        for (std::size_t k = 0; k < measures.size(); ++k) out[measures[k].name] = arrays[k];
        return out;
      },
      py::arg("mesh"), "The .vtu's per-triangle measures: {name: (m,) float64}, in the .vtu's order.");
}

}  // namespace lepp::python
