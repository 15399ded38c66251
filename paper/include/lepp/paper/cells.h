// SPDX-License-Identifier: GPL-3.0-or-later
// The cells of PAPER.md's tables: a run's points added, and its difference to
// the paper's number.
#pragma once
#include <optional>
#include <string>

#include "lepp/paper/run.h"

namespace lepp::paper {

// Points added: "" for no run; "n/a" (engine error), "failed" (no mesh at all),
// "> N (why)" for a run that did not finish (budget, edge floor, time: our guards
// by name; dnf: the others' budget), "N †" for a run that finished by its own
// rule with an angle left below theta, else "N".
std::string points_cell(const Run* r);

// "+D (+P%)": ours minus the paper's, for a finished run with a paper number; else "".
std::string difference_cell(const Run* r, std::optional<int> paper);

}  // namespace lepp::paper
