// SPDX-License-Identifier: GPL-3.0-or-later
// The comparison engines' points added, cached on disk per engine, input, theta
// and method (issue 19: `--compare auto` was 97 % of an audit's time), so a
// second audit of the same inputs runs no comparison at all. One small file per
// entry, named by a 64-bit hash of the key and holding a second, independent
// hash of it (a collision of both is not a concern); written to a temporary
// file and renamed, so parallel audits and threads never read half an entry.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "lepp/pslg.h"
#include "lepp/refine.h"

namespace lepp::audit {

struct CachedPoints {
  bool finished = false;  // the comparison run finished (only then are its points compared)
  double points_added = 0;
  double timeout_seconds = 0;  // the limit it ran under (an unfinished run is reused as it is)
};

class PointsCache {
 public:
  explicit PointsCache(std::string dir = "");  // empty: caches nothing
  bool enabled() const { return !dir_.empty(); }
  const std::string& dir() const { return dir_; }

  // engine_key names the engine and its version ("lepp-reference 0.2.0 abc1234"); an empty key is never cached.
  std::optional<CachedPoints> get(const std::string& engine_key, const Pslg& input, double theta, Method method) const;
  void put(const std::string& engine_key, const Pslg& input, double theta, Method method, const CachedPoints& value) const;

 private:
  std::string dir_;
};

// ${XDG_CACHE_HOME:-$HOME/.cache}/lepp/audit-points; empty when neither is set.
std::string default_points_cache_dir();

}  // namespace lepp::audit
