// SPDX-License-Identifier: GPL-3.0-or-later
// Text made safe for HTML (lepp/html/page.h): every string from an input file
// (a file name, a label, a program's message) goes through here.
#include "lepp/html/page.h"

namespace lepp::html {

std::string escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t' ? ' ' : c;
    }
  }
  return out;
}

}  // namespace lepp::html
