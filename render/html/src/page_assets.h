// SPDX-License-Identifier: GPL-3.0-or-later
// The page's style and scripts, inlined in its <head> (src/page_assets.cpp).
#pragma once

namespace lepp::html::detail {

extern const char* const kStyle;
// First in <head>: script errors, failed loads and console.error calls written into #page-errors.
extern const char* const kErrorHook;
// Pan and zoom of every .pz picture; with #check in the address, the check mode.
extern const char* const kScript;

}  // namespace lepp::html::detail
