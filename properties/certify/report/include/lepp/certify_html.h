// SPDX-License-Identifier: GPL-3.0-or-later
// A certificate as one self-contained HTML page (`lepp certify --html FILE`, and
// the Python report's _repr_html_): the verdict and the counts per kind, the
// statistics, a histogram of the smallest angles against theta, an overview of
// the mesh with every listed violation marked, then each violation with a zoomed
// picture, its exact coordinates and the check's sentence (docs/CERTIFIER.md, "The HTML page").
#pragma once
#include <cstddef>
#include <string>

#include "lepp/certify.h"
#include "lepp/mesh.h"

namespace lepp::certify {

struct HtmlOptions {
  std::string title;                  // what was certified ("corpus/paper/A.poly, out/A"); text, escaped
  std::string command;                // the command line that made the report, shown; text, escaped
  std::size_t shown_per_reason = 5;   // violations of a kind shown at once; the others behind "show all"
  // Above this many triangles the overview draws the mesh's boundary, the constrained edges and
  // the markers only (a page that loads in a browser in seconds at 10^6 triangles).
  std::size_t outline_above = 20000;
};

// What the check that fails with this reason tests, as one sentence (docs/CERTIFIER.md).
const char* explanation(Reason reason);

// The page. Strings from the input (file names, messages) are escaped. Never throws for a
// mesh it cannot draw (ids out of range): the picture is replaced by a line saying why.
std::string html_report(const Mesh& mesh, const Report& report, const HtmlOptions& options = {});

}  // namespace lepp::certify
