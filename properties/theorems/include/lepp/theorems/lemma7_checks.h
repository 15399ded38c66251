// SPDX-License-Identifier: GPL-3.0-or-later
// Lemma 7 (I)'s exact checks with their constant k as a parameter: the tight-constant
// bisection (properties/prove) confirms its refutation at k with the same function the
// row's sampling property calls at the paper's constant (check_lemma7_Ia.. Id).
#pragma once
#include "lepp/theorems/checks.h"

namespace lepp::theorems {

// (a) alpha1 >= k alpha0 (alpha0 <= 30), (b) alpha1 >= k alpha0 (alpha0 <= alpha_limit),
// (c) alpha1 >= k alpha0 (alpha0 <= 5; right triangles: alpha1 = alpha0), (d) beta >= k alpha0.
enum class Lemma7Part { a, b, c, d };
Verdict check_lemma7_I_at(const TerminalQuad& q, Lemma7Part part, double k);

}  // namespace lepp::theorems
