// SPDX-License-Identifier: GPL-3.0-or-later
// The decisions as Markdown: a "decided" column added to the certificate table of
// `lepp theorems` (whose "result" column becomes "sampled"), and the table of tight constants.
#include <cmath>
#include <cstdio>
#include <sstream>

#include "lepp/prove/prove.h"

namespace lepp::prove {
namespace {
std::string seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f s", s);
  return buf;
}
std::string escape(std::string s) {
  for (std::size_t i = 0; (i = s.find('|', i)) != std::string::npos; i += 2) s.replace(i, 1, "\\|");
  return s;
}
std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}
}  // namespace

std::string decided_cell(const Decision& d) {
  switch (d.outcome) {
    case Outcome::Proved:
      return "**proved** (" + d.method + ", " + seconds(d.seconds) + ")" + (d.note.empty() ? "" : ": " + d.note);
    case Outcome::Refuted:
      return "**refuted** (" + d.method + (d.method.rfind("Z3", 0) == 0 ? ", " + seconds(d.seconds) : "") +
             "): " + d.counterexample +
             (d.confirmed ? ", rejected by the row's check function" : " (" + d.note + ")") +
             (d.picture.empty() ? "" : " ([picture](" + d.picture + "))");
    case Outcome::NotDecided: break;
  }
  return "**not decided**: " + d.note;
}

std::string add_decided_column(const std::string& table, const std::vector<Decision>& decisions) {
  std::istringstream in(table);
  std::ostringstream out;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("| where |", 0) == 0) {
      if (auto at = line.rfind("| result |"); at != std::string::npos) line.replace(at, 10, "| sampled |");
      out << line << " decided |\n";
      continue;
    }
    if (line.rfind("|---", 0) == 0) {
      out << line << "---|\n";
      continue;
    }
    std::string cell = "";
    for (const Decision& d : decisions)
      if (line.find("| `" + d.statement + "` |") != std::string::npos) cell = decided_cell(d);
    out << line << (line.rfind("|", 0) == 0 ? " " + escape(cell) + " |" : "") << "\n";
  }
  return out.str();
}

std::string tight_markdown(const std::vector<TightConstant>& rows) {
  std::ostringstream md;
  md << "| where | property | constant's reading | paper | largest proved | smallest refuted | configuration "
        "refuting it (at k) | known extreme | steps, time |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const TightConstant& t : rows) {
    md << "| " << t.where << " | `" << t.statement << "` | " << escape(t.meaning) << " | " << t.paper << " | "
       << (t.complete || t.proved != 0 ? fixed(t.proved, 9) : "-") << " | "
       << (t.complete ? fixed(t.refuted, 9) : "not reached (" + t.stopped + ")") << " | " << escape(t.extreme) << (t.extreme.empty() ? "" : " (k = " + fixed(t.witnessed, 9) + ")")
       << " | " << escape(t.known) << " | " << t.steps << ", " << seconds(t.seconds) << " |\n";
  }
  return md.str();
}

}  // namespace lepp::prove
