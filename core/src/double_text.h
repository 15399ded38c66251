// SPDX-License-Identifier: GPL-3.0-or-later
// A double as the text fmt's "{}" writes for it, byte for byte, made cheaper for the
// .node writer (issue 40, item 2): the digits are fmt's own (Dragonbox, the shortest that
// round-trip); only their layout is written here, and only in fixed notation.
#pragma once

namespace lepp::detail {

// Writes at `at` exactly what fmt::format("{}", x) gives (at most 24 characters) and
// returns the end. Normal doubles that fmt 9 writes in fixed notation (decimal exponent
// from -4 to 15) are laid out here; zero, subnormals, infinities, NaN and exponent
// notation are handed to fmt.
char* write_double(char* at, double x);

}  // namespace lepp::detail
