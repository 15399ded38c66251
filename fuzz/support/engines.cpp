// SPDX-License-Identifier: GPL-3.0-or-later
#include "engines.h"

#include <stdexcept>

#include "lepp/fast.h"
#include "lepp/reference.h"

namespace lepp::fuzz {

const char* to_string(Engine engine) { return engine == Engine::Fast ? "fast" : "reference"; }

bool engine_available(Engine engine) {
  if (engine == Engine::Fast) return lepp::fast::available();
  static const bool reference = [] {
    Pslg triangle;
    triangle.vertices = {{0, 0}, {1, 0}, {0, 1}};
    try {
      lepp::reference::build_cdt(triangle);
      return true;
    } catch (const std::logic_error&) {
      return false;  // the placeholder
    }
  }();
  return reference;
}

Mesh build_cdt(Engine engine, const Pslg& pslg) {
  return engine == Engine::Fast ? lepp::fast::build_cdt(pslg) : lepp::reference::build_cdt(pslg);
}

RefineResult refine(Engine engine, const Pslg& pslg, const RefineOptions& options) {
  return engine == Engine::Fast ? lepp::fast::refine(pslg, options) : lepp::reference::refine(pslg, options);
}

}  // namespace lepp::fuzz
