// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind known_loops.h: loops the paper does not claim away, so a long fuzzing
// run records them and goes on instead of stopping.
#include "known_loops.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <system_error>

#include <unistd.h>

#include "finding.h"
#include "loop_guard.h"

namespace lepp::fuzz {

namespace fs = std::filesystem;

std::string below_resolution_reason(const Pslg& pslg) {
  double extent = 0;
  for (const Point& v : pslg.vertices) extent = std::max({extent, std::fabs(v.x), std::fabs(v.y)});
  // The default edge floor is 2^-20 of the smallest feature (exact unless it underflows).
  const double floor = default_edge_floor(pslg);
  if (extent == 0) return "";
  return floor == 0 || floor < std::ldexp(extent, -60) ? "feature-below-resolution" : "";
}

std::string unclaimed_loop_reason(Method method, double theta_deg, const std::string& loop_class) {
  if (loop_class == "small-angle-cascade") return "small-input-angle";
  if (method == Method::Midpoint && theta_deg > alpha_limit_deg()) return "midpoint-above-alpha-limit";
  if (method == Method::Centroid && theta_deg > 30) return "centroid-above-30";
  return "";
}

std::string band_label(double theta_deg) {
  if (theta_deg <= 20.7) return "10-20.7";
  if (theta_deg <= 22.2) return "20.8-22.2";
  if (theta_deg <= 30) return "22.3-30";
  return "30.1-36";
}

std::string known_finding_key(const std::string& target, const std::string& finding_class, Method method,
                              double theta_deg) {
  return target + "-" + finding_class + "-" + to_string(method) + "-theta" +
         band_label(theta_deg);
}

std::string known_findings_dir() {
  const char* env = std::getenv("LEPP_FUZZ_KNOWN_DIR");
  return env && *env ? env : "known-findings";
}

std::string keep_known_example(const std::string& dir, const std::string& key, const std::uint8_t* data,
                               std::size_t size, const std::string& message) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  const fs::path bin = fs::path(dir) / (key + ".bin");
  if (fs::exists(bin, ec)) return "";
  // Write aside, then link into place: link fails if another job got there first.
  const fs::path tmp = fs::path(dir) / (".tmp-" + key + "-" + std::to_string(::getpid()));
  {
    std::ofstream out(tmp, std::ios::binary);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) return "";
  }
  fs::create_hard_link(tmp, bin, ec);
  fs::remove(tmp);
  if (ec) return "";
  std::ofstream(fs::path(dir) / (key + ".txt")) << message << "\n";
  return bin.string();
}

void report_known_finding(const char* target, const std::string& finding_class, const std::string& reason,
                          const std::string& key, const std::string& message, const std::uint8_t* data,
                          std::size_t size) {
  if (expecting_findings()) {
    std::fprintf(stderr, "LEPP-FINDING target=%s class=%s known=%s : %s\n", target, finding_class.c_str(),
                 reason.c_str(), message.c_str());
    throw FindingReported(finding_class, message);
  }
  const std::string kept = keep_known_example(known_findings_dir(), key, data, size, message);
  std::fprintf(stderr, "LEPP-FINDING target=%s class=%s known=%s%s%s : %s\n", target, finding_class.c_str(),
               reason.c_str(), kept.empty() ? "" : " kept=", kept.c_str(), message.c_str());
}

}  // namespace lepp::fuzz
