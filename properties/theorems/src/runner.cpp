// SPDX-License-Identifier: GPL-3.0-or-later
// Runs a statement's property with fixed parameters (rc::detail::checkProperty,
// the same engine RC_GTEST_PROP uses) and writes the certificate table.
#include <rapidcheck.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <sstream>

#include "lepp/theorems/statements.h"

namespace lepp::theorems {
namespace {
// The certificate prints each counterexample itself; RapidCheck's global listener
// would add a "to reproduce, run with RC_PARAMS=..." note at exit for a run whose
// failures are expected (the findings), which misleads. Replay a row with
// `lepp theorems --only Suite.Name --seed S`, or its gtest with RC_PARAMS.
class QuietListener : public rc::detail::TestListener {
 public:
  void onTestCaseFinished(const rc::detail::CaseDescription&) override {}
  void onShrinkTried(const rc::detail::CaseDescription&, bool) override {}
  void onTestFinished(const rc::detail::TestMetadata&, const rc::detail::TestResult&) override {}
};

// RapidCheck loads its global configuration (RC_PARAMS) on first use and names it on
// stderr with a random seed, which these runs do not use (their parameters fix the
// seed). A command's progress line would be cut by it: it is loaded here once, that
// line dropped and anything else it writes (a bad RC_PARAMS) passed on.
void load_configuration_quietly() {
  static const bool loaded = [] {
    std::ostringstream said;
    std::streambuf* const kept = std::cerr.rdbuf(said.rdbuf());
    rc::detail::configuration();
    std::cerr.rdbuf(kept);
    std::istringstream lines(said.str());
    for (std::string line; std::getline(lines, line);)
      if (line.rfind("Using configuration: ", 0) != 0) std::cerr << line << '\n';
    return true;
  }();
  (void)loaded;
}
}  // namespace

RunOutcome run_statement(const Statement& s, int cases, int inputs, std::uint64_t seed) {
  RunOutcome out;
  auto t0 = std::chrono::steady_clock::now();
  if (s.statistic) {
    bool holds = false;
    out.statistic = s.statistic(inputs, &holds);
    out.passed = holds;
    out.cases = inputs;
    out.applicable = inputs;
  } else {
    load_configuration_quietly();
    rc::detail::TestParams params;
    params.seed = seed;
    params.maxSuccess = cases;
    params.maxSize = 100;
    params.maxDiscardRatio = 10;
    rc::detail::TestMetadata metadata;
    metadata.id = s.suite + "/" + s.name;
    metadata.description = s.name;
    QuietListener quiet;
    auto result = rc::detail::checkProperty(rc::detail::toProperty(s.property), metadata, params, quiet);
    if (result.is<rc::detail::SuccessResult>()) {
      auto success = result.get<rc::detail::SuccessResult>();
      out.passed = true;
      out.cases = success.numSuccess;
      out.applicable = success.numSuccess;
      for (const auto& [tags, count] : success.distribution) {
        // RC_CLASSIFY quotes string tags: "\"hypothesis not met\"".
        auto unquote = [](std::string t) {
          if (t.size() >= 2 && t.front() == '"' && t.back() == '"') t = t.substr(1, t.size() - 2);
          return t;
        };
        std::string key;
        for (const auto& t : tags) key += (key.empty() ? "" : ", ") + unquote(t);
        out.classes[key] += count;
        for (const auto& t : tags)
          if (unquote(t) == "hypothesis not met") out.applicable -= count;
      }
    } else if (result.is<rc::detail::FailureResult>()) {
      auto failure = result.get<rc::detail::FailureResult>();
      out.cases = failure.numSuccess + 1;
      std::ostringstream ss;
      // RC_FAIL's description is "file:line:\nRC_FAIL(v.detail)\n\n<message>": keep the message.
      std::string d = failure.description;
      auto cut = d.rfind("\n\n");
      ss << (cut == std::string::npos ? d : d.substr(cut + 2));
      for (const auto& [type, value] : failure.counterExample) ss << " | " << type << ": " << value;
      out.counterexample = ss.str();
    } else if (result.is<rc::detail::GaveUpResult>()) {
      auto gave = result.get<rc::detail::GaveUpResult>();
      out.gave_up = true;
      out.cases = gave.numSuccess;
      out.counterexample = "gave up: " + gave.description;
    } else {
      out.counterexample = "error: " + result.get<rc::detail::Error>().description;
    }
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

namespace {
const CertificateRow* row_of(const std::vector<CertificateRow>& rows, const std::string& id) {
  for (const auto& r : rows)
    if (r.statement->suite + "." + r.statement->name == id) return &r;
  return nullptr;
}
// A row is fine when it holds, or when it is a documented finding whose
// counterexample reproduced and whose narrowed statement holds.
bool row_ok(const std::vector<CertificateRow>& rows, const CertificateRow& r) {
  if (r.statement->finding.empty()) return r.outcome.passed;
  const CertificateRow* n = row_of(rows, r.statement->narrowed);
  return n && n->outcome.passed;
}
std::string escape(std::string s) {
  for (auto& c : s)
    if (c == '\n') c = ' ';
  for (std::size_t i = 0; (i = s.find('|', i)) != std::string::npos; i += 2) s.replace(i, 1, "\\|");
  return s;
}
}  // namespace

bool certificate_ok(const std::vector<CertificateRow>& rows) {
  for (const auto& r : rows)
    if (!row_ok(rows, r)) return false;
  return true;
}

std::string certificate_markdown(const std::vector<CertificateRow>& rows, bool long_run, int cases, int inputs) {
  std::ostringstream md;
  md << "| where | property | interpretation | cases: default / long | this run (" << (long_run ? "long" : "default")
     << ") | result |\n|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    const Statement& s = *r.statement;
    const RunOutcome& o = r.outcome;
    std::string counts = s.statistic ? std::to_string(kDefaultInputs) + " / " + std::to_string(kLongInputs) + " PSLGs"
                                     : std::to_string(kDefaultCases) + " / " + std::to_string(kLongCases);
    std::string run = s.statistic ? std::to_string(o.cases) + " PSLGs"
                                  : std::to_string(o.cases) + " cases, " + std::to_string(o.applicable) + " applicable";
    if (o.passed && !s.statistic) {
      // What the run exercised: the RC_CLASSIFY classes, most frequent first.
      std::vector<std::pair<int, std::string>> by_count;
      for (const auto& [k, n] : o.classes)
        if (k != "hypothesis not met") by_count.push_back({n, k});
      std::sort(by_count.rbegin(), by_count.rend());
      if (by_count.size() > 4) by_count.resize(4);
      std::string shown;
      for (const auto& [n, k] : by_count) shown += (shown.empty() ? "" : "; ") + k + " " + std::to_string(n);
      if (!shown.empty()) run += " (" + shown + ")";
    }
    std::string result;
    if (s.statistic) {
      result = (o.passed ? "**holds**: " : "**does not hold**: ") + o.statistic;
    } else if (!s.finding.empty()) {
      result = o.passed ? "**finding not reproduced in this run** (the corpus counterexample is still checked by ctest). "
                        : "**counterexample** (documented finding): " + o.counterexample + ". ";
      result += s.finding + " Counterexample kept in `" + s.corpus + "`; narrowed: `" + s.narrowed + "`.";
    } else if (o.passed) {
      result = "**holds**";
    } else {
      result = "**FAILS**: " + o.counterexample;
    }
    md << "| " << s.where << " | `" << s.suite << "." << s.name << "` | " << escape(s.interpretation) << " | " << counts
       << " | " << run << " | " << escape(result) << " |\n";
  }
  (void)cases;
  (void)inputs;
  return md.str();
}

}  // namespace lepp::theorems
