// SPDX-License-Identifier: GPL-3.0-or-later
// fuzz_audit: the audit's verdict code (lepp::audit::check_run: the certifier,
// the conformance replay, the deviation catalogue) on a program's output that
// lies. Input: two length bytes, a PSLG as fuzz_refine encodes it (support/
// fuzz_input.h), then an edit program. The fast engine's correct run (mesh and
// trace) is edited: points moved by ulps or far or made non-finite, triangles
// dropped, flipped, duplicated, degenerate or flat, constrained edges dropped,
// trace points repeated, reordered, put on vertices, outside the domain or made
// non-finite. Every input must end with verdicts: an exception out of check_run
// (documented never to throw) is a finding, and so is a row's internal-error (the
// verdict code stopped on its own guard); a crash, a hang or a sanitizer report
// is libFuzzer's.
#include <cmath>
#include <cstdint>
#include <optional>
#include <limits>
#include <utility>

#include <fmt/format.h>
#include <fuzzer/FuzzedDataProvider.h>

#include "lepp/audit/judge/checks.h"
#include "lepp/engines/registry.h"
#include "lepp/io.h"
#include "lepp/validate.h"
#include "support/finding.h"
#include "support/fuzz_input.h"

using namespace lepp::fuzz;
using lepp::engines::Engine;

namespace {

void finding(const std::string& cls, const std::string& what) { report_finding("fuzz_audit", cls, what); }

// A short correct run: the proven bands only (the engine must end), few points.
constexpr std::int64_t kMaxSteiner = 300;
constexpr int kMaxEdits = 12;

double far_value(FuzzedDataProvider& fdp) {
  static const double values[] = {1e-300, 4.9e-324, 1e-3, 1, 1e6, 1e300, std::numeric_limits<double>::max()};
  return values[fdp.ConsumeIntegralInRange<std::size_t>(0, std::size(values) - 1)];
}

double odd_value(FuzzedDataProvider& fdp) {
  static const double values[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                                  -std::numeric_limits<double>::infinity(), 4.9e-324, -0.0,
                                  std::numeric_limits<double>::max()};
  return values[fdp.ConsumeIntegralInRange<std::size_t>(0, std::size(values) - 1)];
}

double ulps(double x, int k) {
  for (; k > 0; --k) x = std::nextafter(x, INFINITY);
  for (; k < 0; ++k) x = std::nextafter(x, -INFINITY);
  return x;
}

// One edit of the run; `what` collects them for the finding's message.
void edit(lepp::audit::EngineRun& run, FuzzedDataProvider& fdp, std::string& what) {
  lepp::Mesh& m = run.mesh;
  std::vector<lepp::Point>& trace = *run.trace;
  const int kind = fdp.ConsumeIntegralInRange(0, 16);
  const std::size_t pick = fdp.ConsumeIntegral<std::uint16_t>();
  const bool x = fdp.ConsumeBool();
  auto coord = [&](lepp::Point& p) -> double& { return x ? p.x : p.y; };
  const std::size_t nv = m.vertices.size(), nt = m.triangles.size(), np = trace.size();
  what += fmt::format(" {}@{}", kind, pick);
  switch (kind) {
    case 0:  // a vertex moved by a few ulps
      if (nv) coord(m.vertices[pick % nv]) = ulps(coord(m.vertices[pick % nv]), fdp.ConsumeIntegralInRange(-4, 4));
      break;
    case 1:  // a vertex moved far
      if (nv) coord(m.vertices[pick % nv]) += far_value(fdp) * (fdp.ConsumeBool() ? 1 : -1);
      break;
    case 2:  // a vertex not finite, subnormal or huge
      if (nv) coord(m.vertices[pick % nv]) = odd_value(fdp);
      break;
    case 3:  // a triangle dropped
      if (nt) m.triangles.erase(m.triangles.begin() + static_cast<std::ptrdiff_t>(pick % nt));
      break;
    case 4:  // a triangle flipped (clockwise)
      if (nt) std::swap(m.triangles[pick % nt][1], m.triangles[pick % nt][2]);
      break;
    case 5:  // a triangle twice
      if (nt) m.triangles.push_back(m.triangles[pick % nt]);
      break;
    case 6:  // a triangle with a repeated vertex
      if (nt) m.triangles[pick % nt][2] = m.triangles[pick % nt][0];
      break;
    case 7:  // a triangle made flat: its third vertex onto the midpoint of the other two
      if (nt) {
        const lepp::Tri& t = m.triangles[pick % nt];
        const lepp::Point a = m.vertices[t[0]], b = m.vertices[t[1]];
        m.vertices[t[2]] = {(a.x + b.x) / 2, (a.y + b.y) / 2};
      }
      break;
    case 8:  // a triangle's vertex swapped for another vertex of the mesh
      if (nt && nv) m.triangles[pick % nt][fdp.ConsumeIntegralInRange(0, 2)] = static_cast<int>(fdp.ConsumeIntegral<std::uint16_t>() % nv);
      break;
    case 9:  // a constrained edge dropped
      if (!m.constrained_edges.empty()) m.constrained_edges.erase(m.constrained_edges.begin() + static_cast<std::ptrdiff_t>(pick % m.constrained_edges.size()));
      break;
    case 10:  // a trace point twice
      if (np) trace.insert(trace.begin() + static_cast<std::ptrdiff_t>(pick % np), trace[pick % np]);
      break;
    case 11:  // two trace points swapped
      if (np) std::swap(trace[pick % np], trace[fdp.ConsumeIntegral<std::uint16_t>() % np]);
      break;
    case 12:  // a trace point on a vertex (an input vertex or an earlier point)
      if (np && nv) trace[pick % np] = m.vertices[fdp.ConsumeIntegral<std::uint16_t>() % nv];
      break;
    case 13:  // a trace point far away (outside the domain)
      if (np) coord(trace[pick % np]) += far_value(fdp) * (fdp.ConsumeBool() ? 1 : -1);
      break;
    case 14:  // a trace point not finite, subnormal or huge
      if (np) coord(trace[pick % np]) = odd_value(fdp);
      break;
    case 15:  // a trace point moved by a few ulps
      if (np) coord(trace[pick % np]) = ulps(coord(trace[pick % np]), fdp.ConsumeIntegralInRange(-4, 4));
      break;
    case 16:  // a trace point dropped
      if (np) trace.erase(trace.begin() + static_cast<std::ptrdiff_t>(pick % np));
      break;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const std::size_t pslg_size = std::min<std::size_t>(size - 2, data[0] | (data[1] << 8));
  FuzzInput input = decode(data + 2, pslg_size);
  apply_environment(input);
  const std::optional<lepp::Pslg> valid = valid_pslg(input);
  if (!valid) return 0;
  const lepp::Pslg& pslg = *valid;
  lepp::RefineOptions options = options_of(input);
  // Within the proven bands, so that the correct run ends (fuzz_refine hunts the loops).
  options.min_angle_deg = std::min(options.min_angle_deg, options.method == lepp::Method::Centroid ? 28.0 : 20.0);
  options.max_steiner = kMaxSteiner;
  options.trace = true;
  lepp::RefineResult correct;
  try {
    correct = refine(Engine::Fast, pslg, options);
  } catch (const std::exception&) {
    return 0;  // the engine's own findings are fuzz_refine's
  }
  lepp::audit::EngineRequest request;
  request.method = options.method;
  request.theta = options.min_angle_deg;
  lepp::audit::EngineRun run;
  run.status = correct.outcome == lepp::Outcome::Converged || correct.outcome == lepp::Outcome::Unimprovable
                   ? lepp::audit::RunStatus::Ok
                   : lepp::audit::RunStatus::Stopped;
  run.mesh = std::move(correct.mesh);
  run.trace.emplace();
  for (const lepp::TraceStep& s : correct.trace) run.trace->push_back(s.point);

  FuzzedDataProvider fdp(data + 2 + pslg_size, size - 2 - pslg_size);
  std::string edits;
  const int n = fdp.ConsumeIntegralInRange(0, kMaxEdits);
  for (int i = 0; i < n && fdp.remaining_bytes() > 0; ++i) edit(run, fdp, edits);

  lepp::audit::CheckOptions checks;
  checks.arithmetic_double = fdp.ConsumeBool();
  lepp::audit::CaseResult result;
  try {
    result = lepp::audit::check_run(pslg, request, run, checks);
  } catch (const std::exception& e) {
    finding("check-run-threw", fmt::format("{}; edits{}: {}", describe(input), edits, e.what()));
    return 0;
  }
  for (std::size_t r = 0; r < lepp::audit::kRows; ++r)
    if (result.rows[r].verdict == lepp::audit::Verdict::InternalError)
      finding("internal-error", fmt::format("{}; edits{}: row {}: {}", describe(input), edits, r, result.rows[r].detail));
  return 0;
}
