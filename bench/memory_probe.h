// SPDX-License-Identifier: GPL-3.0-or-later
// Peak resident memory of a stretch of code, from /proc/self (Linux): writing 5
// to clear_refs resets VmHWM to the current resident size.
#pragma once
#include <malloc.h>

#include <fstream>
#include <string>

namespace lepp::bench {

inline long status_kb(const char* field) {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(field, 0) == 0) return std::stol(line.substr(line.find(':') + 1));
  return -1;
}

// Starts a measurement: hands memory freed by earlier runs back to the system
// (else it sits in the baseline and hides this run's use), resets the peak and
// returns the resident size now (bytes).
inline long start_peak_measure() {
  malloc_trim(0);
  std::ofstream("/proc/self/clear_refs") << "5";
  return status_kb("VmRSS:") * 1024;
}
// Peak resident size since start_peak_measure, above what was resident then (bytes).
inline long peak_since(long start_bytes) { return status_kb("VmHWM:") * 1024 - start_bytes; }

}  // namespace lepp::bench
