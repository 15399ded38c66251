// SPDX-License-Identifier: GPL-3.0-or-later
// Comparison engines' points added, cached on disk per engine, input, theta and method.
#include "lepp/audit/inputs/points_cache.h"

#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

namespace fs = std::filesystem;

namespace lepp::audit {
namespace {

// Everything the points added depend on, doubles bit for bit (hexfloat).
std::string key_text(const std::string& engine_key, const Pslg& p, double theta, Method method) {
  std::string k = fmt::format("{}\n{}\n{:a}\n{} {} {} {}\n", engine_key, to_string(method), theta, p.vertices.size(),
                              p.segments.size(), p.holes.size(), p.regions.size());
  for (const Point& v : p.vertices) k += fmt::format("{:a} {:a}\n", v.x, v.y);
  for (const Segment& s : p.segments) k += fmt::format("{} {}\n", s.a, s.b);
  for (const Point& h : p.holes) k += fmt::format("{:a} {:a}\n", h.x, h.y);
  for (const Region& r : p.regions) k += fmt::format("{:a} {:a} {:a} {:a}\n", r.at.x, r.at.y, r.attribute, r.max_area);
  return k;
}

std::uint64_t fnv1a(const std::string& s, std::uint64_t h) {
  for (unsigned char c : s) h = (h ^ c) * 0x100000001b3ull;
  return h;
}

}  // namespace

PointsCache::PointsCache(std::string dir) : dir_(std::move(dir)) {}

std::string default_points_cache_dir() {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  if (xdg && *xdg) return (fs::path(xdg) / "lepp" / "audit-points").string();
  const char* home = std::getenv("HOME");
  if (home && *home) return (fs::path(home) / ".cache" / "lepp" / "audit-points").string();
  return "";
}

std::optional<CachedPoints> PointsCache::get(const std::string& engine_key, const Pslg& input, double theta,
                                             Method method) const {
  if (!enabled() || engine_key.empty()) return std::nullopt;
  const std::string k = key_text(engine_key, input, theta, method);
  const std::uint64_t h1 = fnv1a(k, 0xcbf29ce484222325ull), h2 = fnv1a(k, 0x84222325cbf29ce4ull);
  std::ifstream in(fs::path(dir_) / fmt::format("{:016x}", h1));
  std::string magic, check;
  int finished = 0;
  double added = 0, timeout = 0;
  if (!(in >> magic >> check >> finished >> added >> timeout) || magic != "lepp-audit-points-v2" ||
      check != fmt::format("{:016x}", h2))
    return std::nullopt;
  return CachedPoints{finished != 0, added, timeout};
}

void PointsCache::put(const std::string& engine_key, const Pslg& input, double theta, Method method,
                      const CachedPoints& value) const {
  if (!enabled() || engine_key.empty()) return;
  static std::atomic<unsigned> counter{0};
  const std::string k = key_text(engine_key, input, theta, method);
  const std::uint64_t h1 = fnv1a(k, 0xcbf29ce484222325ull), h2 = fnv1a(k, 0x84222325cbf29ce4ull);
  std::error_code ec;
  fs::create_directories(dir_, ec);
  const fs::path final_path = fs::path(dir_) / fmt::format("{:016x}", h1);
  const fs::path tmp = fs::path(dir_) / fmt::format(".{:016x}.{}.{}", h1, getpid(), counter++);
  {
    std::ofstream out(tmp);
    out << fmt::format("lepp-audit-points-v2 {:016x} {} {:.17g} {:.17g}\n", h2, value.finished ? 1 : 0, value.points_added,
                       value.timeout_seconds);
    if (!out) {
      fs::remove(tmp, ec);
      return;  // a cache that cannot be written only costs time
    }
  }
  fs::rename(tmp, final_path, ec);
  if (ec) fs::remove(tmp, ec);
}

}  // namespace lepp::audit
