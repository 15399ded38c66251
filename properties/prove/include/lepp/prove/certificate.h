// SPDX-License-Identifier: GPL-3.0-or-later
// The certificate of `lepp theorems` as one run and one document: the paper's
// statements sampled (properties/theorems), decided for all configurations and
// tightened (this library) when asked, and docs/THEOREMS.md assembled from them,
// the hand-written section after the kept marker carried over from the old file.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "lepp/prove/prove.h"
#include "lepp/theorems/statements.h"

namespace lepp::prove {

struct CertificateRequest {
  bool long_run = false;          // more cases and more PSLGs
  std::vector<std::string> only;  // Suite.Name of the rows to run; empty: every row
  std::uint64_t seed = theorems::kSeed;
  bool prove = false;             // add the "decided" column
  bool tight = false;             // with prove: the tight constants
  double time_limit = 30;         // seconds per solver call and per branch-and-bound
  double tight_time_limit = 10;   // seconds per solver call of the bisection
  std::string corpus = "corpus/theorems";  // the sampled counterexamples
  std::string pictures;           // with prove: draw refuted rows' counterexamples here ("" none)
  std::string table_path;         // where the table goes ("" stdout): the pictures' links are relative to it
};

struct CertificateRun {
  std::string table;        // the certificate table (with the decided column under prove)
  std::string tight_table;  // "" unless tight
  bool ok = false;          // every row holds or is a documented finding; no unconfirmed refutation
  std::vector<Decision> decisions;
};

// Told before and after each step, so a command can show where a long run is.
// `step` is "sample", "prove" or "tighten"; `result` one line, and `detail` the
// counterexample of a failed sample ("" otherwise).
struct CertificateProgress {
  std::function<void(const std::string& step, const std::string& id)> started;
  std::function<void(const std::string& result, const std::string& detail)> finished;
};

// Runs what the request asks. False (with *error) only when the pictures cannot
// be written; a failing row is in the run, not an error.
bool run_certificate(const CertificateRequest& request, const CertificateProgress& progress, CertificateRun* run,
                     std::string* error);

// The line docs/THEOREMS.md's generated part ends at; what follows it is hand-written.
extern const char* const kKeptMarker;

// The whole document: preamble (naming the command's flags and seed), table,
// verdict, tight constants, then the part of `previous` (the file's old text, ""
// if none) from kKeptMarker on.
std::string certificate_document(const CertificateRequest& request, const CertificateRun& run,
                                 const std::string& previous);

}  // namespace lepp::prove
