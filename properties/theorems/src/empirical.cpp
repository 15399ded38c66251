// Section 5 and Remark 15: statistics over generated PSLGs of the paper's class.
#include "properties.h"

namespace lepp::theorems {
void add_empirical_statements(std::vector<Statement>& rows) { (void)rows; }
}  // namespace lepp::theorems
