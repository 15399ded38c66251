// SPDX-License-Identifier: GPL-3.0-or-later
// The geometric half of validate(): what needs exact predicates and a
// triangulation (CGAL, kept out of every header). Internal to lepp_core.
#pragma once
#include <string>
#include <vector>

#include "lepp/pslg.h"

namespace lepp::detail {

// Collects warnings of one kind, keeping the first few in full and counting
// the rest, so a hostile file with a million duplicates cannot flood memory.
class WarningSink {
 public:
  WarningSink(std::vector<std::string>& out, std::string kind, std::size_t keep = 20)
      : out_(out), kind_(std::move(kind)), keep_(keep) {}
  ~WarningSink();
  void add(std::string message);
  WarningSink(const WarningSink&) = delete;
  WarningSink& operator=(const WarningSink&) = delete;

 private:
  std::vector<std::string>& out_;
  std::string kind_;  // for the summary line, e.g. "duplicate vertex"
  std::size_t keep_;
  std::size_t count_ = 0;
};

// "file:line" or "file" (line 0 or no file name).
std::string where(const std::string& file, int line);

// Input: vertices distinct and finite, segments with distinct endpoints and
// ids in range (validate() checks these first). Replaces pslg.segments (and
// segment_lines) by the pieces between consecutive vertices along each
// segment, each kept once, in input order; warns about splits, repeats,
// overlaps and useless hole points; throws InputError on crossing segments,
// collinear input and an empty domain.
void check_geometry(Pslg& pslg, std::vector<std::string>& warnings);

// validate(), splitting crossing segments first when `split_crossings` is set.
Pslg validate(const Pslg& input, bool split_crossings, std::vector<std::string>& warnings);

}  // namespace lepp::detail
