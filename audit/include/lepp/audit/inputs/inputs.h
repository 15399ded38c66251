// SPDX-License-Identifier: GPL-3.0-or-later
// Where the audit's inputs come from: RapidCheck's PSLG generators (with their
// shrink trees, so a failure shrinks through the engine), the paper's problems
// (corpus/paper), the other .poly files of corpus/, and the user's directories.
// Deterministic for a seed.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lepp/pslg.h"

namespace lepp::audit {

// RapidCheck's shrink tree of a generated input, opaque here: only the audit's
// sources see RapidCheck (src/inputs/shrink_tree.h).
struct ShrinkTree;

struct AuditInput {
  std::string name;    // "gen:convex seed 7 #12", "corpus/paper/A.poly", a user path
  std::string path;    // the file it was read from; empty for generated inputs
  Pslg pslg;           // validated
  std::shared_ptr<const ShrinkTree> shrink_tree;  // generated inputs: the shrink tree (raw, not validated)
};

struct InputSources {
  bool generated = true;             // RapidCheck's families (lepp/gen.h)
  bool paper = true;                 // SOURCE_ROOT/corpus/paper/*.poly
  bool corpus = true;                // SOURCE_ROOT/corpus/hostile/*.poly (those that validate)
  std::vector<std::string> dirs;     // the user's: every *.poly in them (sorted); when given, only these
  std::string source_root = ".";     // where corpus/ is
  std::uint64_t seed = 1;
  std::size_t count = 100;           // how many inputs at most
  int max_size = 60;                 // RapidCheck size of the last generated input (sizes ramp up from 0)
};

// The inputs in a fixed order: files first (user's, paper, corpus), then
// generated ones up to `count`. Files that do not read or validate are skipped
// with a note in `skipped`. Throws UsageError for a missing user directory.
std::vector<AuditInput> collect_inputs(const InputSources& sources, std::vector<std::string>& skipped);

// The i-th generated input for a seed (families alternate between lepp::gen::anyPslg
// and lepp::gen::wellShapedPslg). nullopt when the generated PSLG does not validate.
std::optional<AuditInput> generated_input(std::uint64_t seed, std::size_t index, int size);

// Reads and validates a .poly file; nullopt and `why` when it does not.
std::optional<Pslg> read_validated(const std::string& path, std::string& why);

}  // namespace lepp::audit
