// SPDX-License-Identifier: GPL-3.0-or-later
// The registry: engine names, method and order spellings, lepp's engines by name.
#include "lepp/engines/registry.h"

#include <stdexcept>

#include "lepp/fast.h"
#include "lepp/reference.h"

namespace lepp::engines {

const char* to_string(Engine engine) {
  switch (engine) {
    case Engine::Fast: return "fast";
    case Engine::Reference: return "reference";
    case Engine::Triangle: return "triangle";
    case Engine::Cgal: return "cgal";
    case Engine::Command: return "cmd";
  }
  return "?";
}

const std::vector<Engine>& all_engines() {
  static const std::vector<Engine> engines = {Engine::Fast, Engine::Reference, Engine::Triangle, Engine::Cgal,
                                              Engine::Command};
  return engines;
}

const std::vector<Engine>& lepp_engines() {
  static const std::vector<Engine> engines = {Engine::Fast, Engine::Reference};
  return engines;
}

const std::vector<Engine>& audit_engines() {
  static const std::vector<Engine> engines = {Engine::Fast, Engine::Reference, Engine::Triangle, Engine::Cgal};
  return engines;
}

const std::vector<Engine>& comparison_engines() {
  static const std::vector<Engine> engines = {Engine::Reference, Engine::Fast, Engine::Triangle, Engine::Cgal};
  return engines;
}

const std::vector<Engine>& auto_comparisons() {
  static const std::vector<Engine> engines = {Engine::Reference, Engine::Triangle};
  return engines;
}

const std::vector<QueueOrder>& audit_orders() {
  static const std::vector<QueueOrder> orders = {QueueOrder::Fifo, QueueOrder::Lifo};
  return orders;
}

std::string audit_title(Engine engine, QueueOrder order) {
  if (is_lepp_engine(engine))
    return std::string("lepp ") + to_string(engine) + (order == QueueOrder::Fifo ? "" : std::string(" (") + to_string(order) + ")");
  if (engine == Engine::Triangle) return "Triangle (triangle-wasm)";
  if (engine == Engine::Cgal) return "CGAL refine_Delaunay_mesh_2";
  throw std::invalid_argument("a command engine is named by its template");
}

std::string comparison_title(Engine engine) {
  if (is_lepp_engine(engine)) return std::string("lepp ") + to_string(engine);
  if (engine == Engine::Triangle) return "Triangle";
  if (engine == Engine::Cgal) return "CGAL";
  throw std::invalid_argument("a command engine is no comparison");
}

bool is_lepp_engine(Engine engine) { return engine == Engine::Fast || engine == Engine::Reference; }

std::optional<Engine> parse_engine(const std::string& name, const std::vector<Engine>& choices) {
  for (Engine e : choices)
    if (name == to_string(e)) return e;
  return std::nullopt;
}

std::optional<Method> parse_method(const std::string& name) {
  Method method = Method::Centroid;
  if (!lepp::parse_method(name, method)) return std::nullopt;
  return method;
}

std::optional<QueueOrder> parse_order(const std::string& name) {
  QueueOrder order = QueueOrder::Fifo;
  if (!parse_queue_order(name, order)) return std::nullopt;
  return order;
}

std::vector<std::string> names(const std::vector<Engine>& engines) {
  std::vector<std::string> out;
  for (Engine e : engines) out.push_back(to_string(e));
  return out;
}

std::vector<std::string> method_names() {
  std::vector<std::string> out;
  for (Method m : all_methods()) out.push_back(to_string(m));
  return out;
}

std::vector<std::string> order_names() { return order_names(all_queue_orders()); }

std::vector<std::string> order_names(const std::vector<QueueOrder>& orders) {
  std::vector<std::string> out;
  for (QueueOrder o : orders) out.push_back(to_string(o));
  return out;
}

std::string quoted_choices(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += i + 1 == names.size() ? " or " : ", ";
    out += "'" + names[i] + "'";
  }
  return out;
}

RefineFunction refine_function(Engine engine) {
  if (engine == Engine::Fast) return &fast::refine;
  if (engine == Engine::Reference) return &reference::refine;
  throw std::invalid_argument(std::string("not one of lepp's engines: ") + to_string(engine));
}

RefineResult refine(Engine engine, const Pslg& validated, const RefineOptions& options) {
  return refine_function(engine)(validated, options);
}

Mesh build_cdt(Engine engine, const Pslg& validated) {
  if (engine == Engine::Fast) return fast::build_cdt(validated);
  if (engine == Engine::Reference) return reference::build_cdt(validated);
  throw std::invalid_argument(std::string("not one of lepp's engines: ") + to_string(engine));
}

}  // namespace lepp::engines
