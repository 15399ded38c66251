// Placeholder until the reference engine lands.
#include <stdexcept>

#include "lepp/reference.h"

namespace lepp::reference {
Mesh build_cdt(const Pslg&) { throw std::logic_error("the reference engine is not implemented yet"); }
RefineResult refine(const Pslg&, const RefineOptions&) { throw std::logic_error("the reference engine is not implemented yet"); }
}  // namespace lepp::reference
