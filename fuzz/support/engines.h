// SPDX-License-Identifier: GPL-3.0-or-later
// The two engines behind one switch, and whether each is implemented yet
// (the placeholders throw std::logic_error; a fuzz target then skips them).
#pragma once
#include "lepp/mesh.h"
#include "lepp/pslg.h"
#include "lepp/refine.h"

namespace lepp::fuzz {

enum class Engine { Fast, Reference };
const char* to_string(Engine engine);

bool engine_available(Engine engine);
Mesh build_cdt(Engine engine, const Pslg& pslg);
RefineResult refine(Engine engine, const Pslg& pslg, const RefineOptions& options);

}  // namespace lepp::fuzz
