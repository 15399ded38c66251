// SPDX-License-Identifier: GPL-3.0-or-later
// What the numbers a program wrote say about its arithmetic (docs/CONFORMANCE.md,
// "Arithmetic"): coordinates held as `float` (single-precision), the input read
// as `float` and the rest computed in double (float-input), or written with
// fewer significant digits than a double needs (printed-digits). A
// certificate or conformance finding names these first: the gaps, moved
// vertices and near misses they cause are their consequence, not the program's
// algorithm. Read from the output alone (the mesh's vertices, the trace's
// points) against the input and the paper's choices; exact comparisons of doubles.
#pragma once
#include <cstddef>
#include <string>

#include "lepp/audit/judge/conformance.h"
#include "lepp/mesh.h"
#include "lepp/pslg.h"

namespace lepp::audit {

struct ArithmeticEvidence {
  std::string name;         // "single-precision", "float-input", "printed-digits", or "" (nothing shows)
  int digits = 0;           // printed-digits: the most significant digits of any coordinate written
  std::size_t moved = 0;    // input vertices the output has at their rounding instead of where they are
  std::size_t rounded = 0;  // input vertices that rounding moves (the others tell nothing)
  std::string what;         // one line for a finding, after the name: what the output shows
};

// From the final mesh: every input vertex that the rounding moves is in the
// output at its rounding, none where it is (and at least one). printed-digits
// is tried first (the coarser rounding), with D the most significant digits of
// any output coordinate (D <= 16); then the float rounding: single-precision
// when every output coordinate is a float, float-input when some are not.
ArithmeticEvidence mesh_arithmetic(const Pslg& input, const Mesh& mesh);

// From a failing conformance step: the program's point is a rounding of the
// paper's nearest choice there that the choice itself is not: a float within
// the point tolerance scaled from DBL_EPSILON to FLT_EPSILON, or a point of
// D <= 16 significant digits within half a unit of its D-th digit.
ArithmeticEvidence step_arithmetic(const ConformanceFailure& failure);

// One sentence each, as in docs/CONFORMANCE.md.
const char* arithmetic_definition(const std::string& name);

}  // namespace lepp::audit
