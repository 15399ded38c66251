// Placeholder until the fast engine lands (issue: the optimized engine).
#include <stdexcept>

#include "lepp/fast.h"

namespace lepp::fast {
bool available() { return false; }
Mesh build_cdt(const Pslg&) { throw std::logic_error("the fast engine is not implemented yet; use --engine reference"); }
RefineResult refine(const Pslg&, const RefineOptions&) {
  throw std::logic_error("the fast engine is not implemented yet; use --engine reference");
}
}  // namespace lepp::fast
