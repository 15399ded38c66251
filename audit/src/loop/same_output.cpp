// SPDX-License-Identifier: GPL-3.0-or-later
// Two runs' outputs compared bit for bit (loop/same_output.h).
#include "loop/same_output.h"

#include <cstring>

#include <fmt/format.h>


namespace lepp::audit::loop {
namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

bool same_output(const EngineRun& a, const EngineRun& b, std::string& why) {
  if (a.status != b.status) {
    why = fmt::format("one run {}, the other {}", to_string(a.status), to_string(b.status));
    return false;
  }
  if (a.exit_code != b.exit_code || a.signal != b.signal) {
    why = fmt::format("exit status {} and {}, signal {} and {}", a.exit_code, b.exit_code, a.signal, b.signal);
    return false;
  }
  if (a.mesh.vertices.size() != b.mesh.vertices.size() || a.mesh.triangles.size() != b.mesh.triangles.size()) {
    why = fmt::format("{} vertices and {} triangles, then {} and {}", a.mesh.vertices.size(), a.mesh.triangles.size(),
                      b.mesh.vertices.size(), b.mesh.triangles.size());
    return false;
  }
  for (std::size_t i = 0; i < a.mesh.vertices.size(); ++i)
    if (!same_bits(a.mesh.vertices[i].x, b.mesh.vertices[i].x) || !same_bits(a.mesh.vertices[i].y, b.mesh.vertices[i].y)) {
      why = fmt::format("vertex {} at ({:.17g}, {:.17g}), then at ({:.17g}, {:.17g})", i, a.mesh.vertices[i].x,
                        a.mesh.vertices[i].y, b.mesh.vertices[i].x, b.mesh.vertices[i].y);
      return false;
    }
  for (std::size_t i = 0; i < a.mesh.triangles.size(); ++i)
    if (a.mesh.triangles[i] != b.mesh.triangles[i]) {
      why = fmt::format("triangle {} differs", i);
      return false;
    }
  if (a.trace.has_value() != b.trace.has_value() || (a.trace && a.trace->size() != b.trace->size())) {
    why = "the traces differ in length";
    return false;
  }
  if (a.trace)
    for (std::size_t i = 0; i < a.trace->size(); ++i)
      if (!same_bits((*a.trace)[i].x, (*b.trace)[i].x) || !same_bits((*a.trace)[i].y, (*b.trace)[i].y)) {
        why = fmt::format("trace point {} differs", i + 1);
        return false;
      }
  return true;
}

}  // namespace lepp::audit::loop
