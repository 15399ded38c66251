// SPDX-License-Identifier: GPL-3.0-or-later
// render: the SVG drawing of `lepp render`, highlights included.
#include <array>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "lepp/render.h"

namespace lepp::python {

void bind_render(py::module_& m) {
  m.def(
      "render_svg",
      [](const py::dict& mesh, const std::string& color, bool highlight_bad, double min_angle, double width,
         const std::string& title, const std::vector<int>& triangles, const std::vector<std::array<double, 2>>& points) {
        if (color != "quality" && color != "angle") throw std::invalid_argument("color: 'quality' or 'angle'");
        if (!(width >= 100 && width <= 20000)) throw std::invalid_argument("width: must be in [100, 20000] pixels");
        Mesh m = mesh_from_dict(mesh);
        render::RenderOptions o;
        o.color = color == "angle" ? render::ColorBy::Angle : render::ColorBy::Quality;
        o.highlight_bad = highlight_bad;
        o.min_angle_deg = min_angle;
        o.width = width;
        o.title = title;
        if (!triangles.empty() || !points.empty()) {
          render::Highlight h;
          h.triangles = triangles;
          for (const auto& p : points) h.points.push_back({p[0], p[1]});
          o.highlights.push_back(h);
        }
        py::gil_scoped_release release;
        return render::render_svg(m, o);
      },
      py::arg("mesh"), py::arg("color") = "quality", py::arg("highlight_bad") = false, py::arg("min_angle") = 30.0,
      py::arg("width") = 1000.0, py::arg("title") = "", py::arg("triangles") = std::vector<int>(),
      py::arg("points") = std::vector<std::array<double, 2>>(), "The SVG document of lepp render.");
}

}  // namespace lepp::python
