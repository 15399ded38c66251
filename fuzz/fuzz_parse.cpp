// SPDX-License-Identifier: GPL-3.0-or-later
// fuzz_parse: bytes into the .poly reader and validation. Every input either
// parses or is rejected with lepp::InputError; nothing else may escape, and a
// lying header may not make the reader allocate (run with -malloc_limit_mb).
// A parsed PSLG written back with write_poly must read back unchanged.
//
// If the input contains the line "@node", what follows it is written to the
// .node file beside the .poly, so the ".poly with no vertices" path is fuzzed too.
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

#include <fcntl.h>
#include <unistd.h>

#include "lepp/io.h"
#include "lepp/validate.h"
#include "support/finding.h"

namespace {

const std::string& base_path() {
  static const std::string base = [] {
    const char* tmp = std::getenv("TMPDIR");
    return std::string(tmp && *tmp ? tmp : "/tmp") + "/lepp-fuzz-parse-" + std::to_string(getpid());
  }();
  return base;
}

// A fresh file each time: truncating one that holds data makes ext4 flush it at close
// (auto_da_alloc), which cost the target 95 % of its wall time on this machine. Written
// with write(2), no stream: an ofstream's 8 KiB buffer was fresh pages under ASan.
void write_file(const std::string& path, std::string_view bytes) {
  std::remove(path.c_str());
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return;  // read_poly then names the missing file, a clean rejection
  for (std::size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n <= 0) break;
    done += static_cast<std::size_t>(n);
  }
  ::close(fd);
}

void finding(const std::string& cls, const std::string& what) { lepp::fuzz::report_finding("fuzz_parse", cls, what); }

bool same_pslg(const lepp::Pslg& a, const lepp::Pslg& b) {
  if (a.vertices != b.vertices || a.holes != b.holes || a.segments.size() != b.segments.size()) return false;
  for (std::size_t i = 0; i < a.segments.size(); ++i)
    if (a.segments[i].a != b.segments[i].a || a.segments[i].b != b.segments[i].b) return false;
  return true;
}

void check_round_trip(const lepp::Pslg& pslg) {
  const std::string path = base_path() + "-roundtrip.poly";
  std::remove(path.c_str());  // a fresh file (write_file above says why)
  lepp::write_poly(path, pslg);
  lepp::Pslg back;
  try {
    back = lepp::read_poly(path);
  } catch (const lepp::InputError& e) {
    finding("round-trip-rejected", e.what());
  }
  if (!same_pslg(pslg, back)) finding("round-trip-changed", "write_poly then read_poly changed the PSLG");
}

void check_validated(const lepp::Pslg& p) {
  const int n = static_cast<int>(p.vertices.size());
  for (const lepp::Segment& s : p.segments)
    if (s.a < 0 || s.a >= n || s.b < 0 || s.b >= n || s.a == s.b)
      finding("validate-bad-segment", "validate() returned a segment with a bad or repeated endpoint");
  for (std::size_t i = 1; i < p.vertices.size(); ++i)
    for (std::size_t j = 0; j < i && p.vertices.size() <= 512; ++j)
      if (p.vertices[i] == p.vertices[j]) finding("validate-duplicate", "validate() kept a duplicate vertex");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const std::string poly = base_path() + ".poly", node = base_path() + ".node";
  if (std::size_t at = bytes.find("@node\n"); at != std::string_view::npos) {
    write_file(poly, bytes.substr(0, at));
    write_file(node, bytes.substr(at + 6));
  } else {
    write_file(poly, bytes);
    std::remove(node.c_str());
  }
  lepp::Pslg parsed;
  try {
    parsed = lepp::read_poly(poly);
  } catch (const lepp::InputError&) {
    return 0;  // a clean rejection
  } catch (const std::exception& e) {
    finding("read-unexpected-exception", e.what());
    return 0;
  }
  check_round_trip(parsed);
  try {
    std::vector<std::string> warnings;
    check_validated(lepp::validate(parsed, warnings));
  } catch (const lepp::InputError&) {
  } catch (const std::exception& e) {
    finding("validate-unexpected-exception", e.what());
  }
  return 0;
}
