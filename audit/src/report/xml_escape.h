// SPDX-License-Identifier: GPL-3.0-or-later
// Text put into XML by the audit (private to lepp_audit): the JUnit report's
// names and messages, the titles of the findings' SVG pictures.
#pragma once
#include <string>

namespace lepp::audit::detail {

// s safe inside an XML attribute or element: < > & " ' as entities, control
// characters other than newline and tab (not allowed in XML 1.0) as spaces.
std::string xml_escape(const std::string& s);

}  // namespace lepp::audit::detail
