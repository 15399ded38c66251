// SPDX-License-Identifier: GPL-3.0-or-later
// Text escaped for XML: the JUnit report and the SVG titles.
#include "xml_escape.h"

namespace lepp::audit::detail {

std::string xml_escape(const std::string& s) {
  std::string r;
  for (char c : s) {
    if (c == '<') r += "&lt;";
    else if (c == '>') r += "&gt;";
    else if (c == '&') r += "&amp;";
    else if (c == '"') r += "&quot;";
    else if (c == '\'') r += "&apos;";
    else if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') r += ' ';
    else r += c;
  }
  return r;
}

}  // namespace lepp::audit::detail
