// SPDX-License-Identifier: GPL-3.0-or-later
// Deterministic property runs by default: a fixed seed and a test count chosen
// for the default ctest run, unless RC_PARAMS is set (then it decides entirely,
// e.g. RC_PARAMS="reproduce=..." or "max_success=1000").
#include <cstdlib>

namespace {
const int kDefaults = (setenv("RC_PARAMS", LEPP_RC_DEFAULTS, /*overwrite=*/0), 0);
}  // namespace
