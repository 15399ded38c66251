// SPDX-License-Identifier: GPL-3.0-or-later
// Every engine lepp can run, named once: lepp's own (fast, reference), the peers
// (Triangle, CGAL's mesher) and any program through a command template; the
// spellings of the methods and processing orders; and lepp's own engines run
// in process by name. Every command, binding and tool asks here.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "lepp/mesh.h"
#include "lepp/pslg.h"
#include "lepp/refine.h"

namespace lepp::engines {

enum class Engine {
  Fast,       // lepp's fast engine (impl/): flat arrays, filtered exact predicates
  Reference,  // lepp's exact engine on CGAL Epeck (reference/): the oracle
  Triangle,   // Shewchuk's Triangle, the triangle-wasm build under node (engines/others)
  Cgal,       // CGAL's refine_Delaunay_mesh_2 (engines/others)
  Command,    // any program, through `lepp audit --cmd TEMPLATE`
};

// The name a user types: fast, reference, triangle, cgal; "cmd" for the command template.
const char* to_string(Engine engine);
// Every engine, in the order above.
const std::vector<Engine>& all_engines();
// lepp's own engines, run in process (refine, build_cdt below): fast, reference.
const std::vector<Engine>& lepp_engines();
// The engines `lepp audit --engine NAME` runs: lepp's own, then Triangle and CGAL.
const std::vector<Engine>& audit_engines();
// The engines `lepp audit --compare NAME` counts points against, and those of --compare auto.
const std::vector<Engine>& comparison_engines();
const std::vector<Engine>& auto_comparisons();
// The orders `lepp audit --order` gives lepp's engines: fifo, lifo.
const std::vector<QueueOrder>& audit_orders();
bool is_lepp_engine(Engine engine);

// The audit report's name of an engine under audit ("lepp fast (lifo)", "Triangle (triangle-wasm)")
// and of a comparison ("lepp reference", "CGAL"). Not for Engine::Command (the template names it).
std::string audit_title(Engine engine, QueueOrder order = QueueOrder::Fifo);
std::string comparison_title(Engine engine);

// The engine of NAME among CHOICES; nothing for a name that is not one of them.
std::optional<Engine> parse_engine(const std::string& name, const std::vector<Engine>& choices = all_engines());
std::optional<Method> parse_method(const std::string& name);
std::optional<QueueOrder> parse_order(const std::string& name);

// The names, in order: for a command line's choice check and for messages.
std::vector<std::string> names(const std::vector<Engine>& engines);
std::vector<std::string> method_names();                    // centroid, midpoint
std::vector<std::string> order_names();                     // fifo, lifo, flip, random, smallest-angle, batch
std::vector<std::string> order_names(const std::vector<QueueOrder>& orders);
// "'a', 'b' or 'c'": the choices as a message lists them.
std::string quoted_choices(const std::vector<std::string>& names);

// lepp's own engine, in process. Throws std::invalid_argument for an engine that is not lepp's.
using RefineFunction = RefineResult (*)(const Pslg&, const RefineOptions&);
using CdtFunction = Mesh (*)(const Pslg&);
RefineFunction refine_function(Engine engine);
RefineResult refine(Engine engine, const Pslg& validated, const RefineOptions& options);
// The CDT of a validated PSLG with exterior and holes removed (Triangle's -p).
Mesh build_cdt(Engine engine, const Pslg& validated);

}  // namespace lepp::engines
