// SPDX-License-Identifier: GPL-3.0-or-later
// Bytes as base64 (RFC 4648, padded): pictures inlined as data: URIs.
#pragma once
#include <string>
#include <string_view>

namespace lepp::html {

std::string base64(std::string_view bytes);

}  // namespace lepp::html
