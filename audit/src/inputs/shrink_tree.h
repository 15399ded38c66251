// SPDX-License-Identifier: GPL-3.0-or-later
// RapidCheck's shrink tree of a generated input, behind the opaque
// lepp::audit::ShrinkTree of lepp/audit/inputs/inputs.h (private to lepp_audit):
// only generated inputs (inputs.cpp) and the shrinker (shrink/shrink.cpp) see
// RapidCheck, so the audit's public headers, and who includes them, do not.
#pragma once
#include <rapidcheck.h>

#include "lepp/pslg.h"

namespace lepp::audit {

struct ShrinkTree {
  rc::Shrinkable<Pslg> root;  // raw PSLGs, not validated
};

}  // namespace lepp::audit
