// SPDX-License-Identifier: GPL-3.0-or-later
#include "lepp/audit/shrink.h"

#include <chrono>
#include <optional>

#include "lepp/validate.h"

namespace lepp::audit {
namespace {

using Clock = std::chrono::steady_clock;

std::optional<Pslg> validated(const Pslg& p) {
  try {
    std::vector<std::string> warnings;
    Pslg v = validate(p, warnings);
    v.source = p.source;
    return v;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// Plain copy without line bookkeeping (shrunk PSLGs come from no file).
Pslg bare(const Pslg& p) {
  Pslg q;
  q.vertices = p.vertices;
  q.segments = p.segments;
  q.holes = p.holes;
  q.source = p.source;
  return q;
}

Pslg without_vertex(const Pslg& p, int v) {
  Pslg q;
  q.source = p.source;
  for (std::size_t i = 0; i < p.vertices.size(); ++i)
    if (static_cast<int>(i) != v) q.vertices.push_back(p.vertices[i]);
  for (const Segment& s : p.segments) {
    if (s.a == v || s.b == v) continue;
    q.segments.push_back({s.a > v ? s.a - 1 : s.a, s.b > v ? s.b - 1 : s.b, s.marker});
  }
  q.holes = p.holes;
  return q;
}

}  // namespace

ShrinkResult shrink_pslg(const Pslg& start, const std::function<bool(const Pslg&)>& still_fails, const ShrinkLimits& limits) {
  ShrinkResult r;
  r.pslg = start;
  const auto t0 = Clock::now();
  auto out_of_budget = [&] {
    return r.runs >= limits.max_runs || std::chrono::duration<double>(Clock::now() - t0).count() > limits.max_seconds;
  };
  auto attempt = [&](const Pslg& candidate) {
    if (out_of_budget()) return false;
    auto v = validated(candidate);
    if (!v) return false;
    ++r.runs;
    if (!still_fails(*v)) return false;
    r.pslg = std::move(*v);
    ++r.steps;
    return true;
  };
  bool progress = true;
  while (progress && !out_of_budget()) {
    progress = false;
    Pslg cur = bare(r.pslg);
    // Holes, then segments, then vertices (with their segments): each removal kept if it still fails.
    for (std::size_t i = cur.holes.size(); i-- > 0 && !progress;) {
      Pslg c = cur;
      c.holes.erase(c.holes.begin() + static_cast<long>(i));
      progress = attempt(c);
    }
    // Halves first: big inputs shrink in few runs.
    for (std::size_t chunk = cur.segments.size() / 2; chunk >= 1 && !progress; chunk /= 2)
      for (std::size_t at = 0; at + chunk <= cur.segments.size() && !progress; at += chunk) {
        Pslg c = cur;
        c.segments.erase(c.segments.begin() + static_cast<long>(at), c.segments.begin() + static_cast<long>(at + chunk));
        progress = attempt(c);
      }
    for (std::size_t i = cur.vertices.size(); i-- > 0 && !progress;) progress = attempt(without_vertex(cur, static_cast<int>(i)));
  }
  return r;
}

ShrinkResult shrink_input(const AuditInput& input, const std::function<bool(const Pslg&)>& still_fails,
                          const ShrinkLimits& limits) {
  if (!input.shrinkable) return shrink_pslg(input.pslg, still_fails, limits);
  ShrinkResult r;
  r.pslg = input.pslg;
  const auto t0 = Clock::now();
  rc::Shrinkable<Pslg> cur = *input.shrinkable;
  bool progress = true;
  while (progress) {
    progress = false;
    auto shrinks = cur.shrinks();
    while (auto s = shrinks.next()) {
      if (r.runs >= limits.max_runs || std::chrono::duration<double>(Clock::now() - t0).count() > limits.max_seconds)
        return r;
      std::optional<Pslg> v;
      try {
        v = validated(s->value());
      } catch (const std::exception&) {
        v.reset();
      }
      if (!v) continue;
      ++r.runs;
      if (!still_fails(*v)) continue;
      r.pslg = std::move(*v);
      ++r.steps;
      cur = *s;
      progress = true;
      break;
    }
  }
  // The tree is exhausted: what is left may still shrink by dropping parts.
  ShrinkLimits rest = limits;
  rest.max_runs = limits.max_runs > r.runs ? limits.max_runs - r.runs : 0;
  rest.max_seconds = limits.max_seconds - std::chrono::duration<double>(Clock::now() - t0).count();
  if (rest.max_runs > 0 && rest.max_seconds > 0) {
    ShrinkResult more = shrink_pslg(r.pslg, still_fails, rest);
    r.pslg = std::move(more.pslg);
    r.steps += more.steps;
    r.runs += more.runs;
  }
  return r;
}

}  // namespace lepp::audit
