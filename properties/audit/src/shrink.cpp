// SPDX-License-Identifier: GPL-3.0-or-later
#include "lepp/audit/shrink.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <vector>

#include "lepp/validate.h"
#include "shrink_moves.h"

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
  q.vertex_markers = p.vertex_markers;
  q.segments = p.segments;
  q.holes = p.holes;
  q.source = p.source;
  return q;
}

template <class T>
void erase_range(std::vector<T>& v, std::size_t first, std::size_t last) {
  v.erase(v.begin() + static_cast<long>(first), v.begin() + static_cast<long>(last));
}

std::vector<char> flags(std::size_t n, const std::vector<int>& ids) {
  std::vector<char> f(n, 0);
  for (int i : ids) f[static_cast<std::size_t>(i)] = 1;
  return f;
}

// The greedy shrinker: edits that keep the PSLG valid (detail::), each kept when
// the engine still fails on the result; every engine run counts against the limits.
class Greedy {
 public:
  Greedy(const Pslg& start, const std::function<bool(const Pslg&)>& still_fails, const ShrinkLimits& limits)
      : still_fails_(still_fails), limits_(limits), t0_(Clock::now()) {
    r_.pslg = start;
  }

  ShrinkResult run() {
    // Structural edits to a fixed point, then simpler coordinates (which may
    // let more go: vertices that become collinear, ...), again.
    while (!out_of_budget()) {
      while (!out_of_budget() && structural_pass()) {
      }
      if (!coordinates()) break;
    }
    return r_;
  }

 private:
  using Count = std::function<std::size_t(const Pslg&)>;
  using Remove = std::function<Pslg(const Pslg&, std::size_t, std::size_t)>;

  bool out_of_budget() const {
    return r_.runs >= limits_.max_runs ||
           std::chrono::duration<double>(Clock::now() - t0_).count() > limits_.max_seconds;
  }

  static std::size_t size(const Pslg& p) { return p.vertices.size() + p.segments.size() + p.holes.size(); }

  // A candidate that does not validate costs no engine run. Structural edits
  // must make the validated PSLG smaller (validation may split a segment at a
  // vertex), coordinate edits must not make it larger: the loop cannot cycle.
  bool attempt(const Pslg& candidate, bool structural = true) {
    if (out_of_budget()) return false;
    auto v = validated(candidate);
    if (!v) return false;
    if (structural ? size(*v) >= size(r_.pslg) : size(*v) > size(r_.pslg)) return false;
    ++r_.runs;
    if (!still_fails_(*v)) return false;
    r_.pslg = std::move(*v);
    ++r_.steps;
    return true;
  }

  // Removes chunks of the items count() lists, halves first (a big input goes
  // in few runs), down to single items; after a kept removal the same position
  // is tried again, since the later items moved up.
  bool remove_chunks(const Count& count, const Remove& remove) {
    bool any = false;
    const std::size_t n = count(r_.pslg);
    for (std::size_t chunk = std::max<std::size_t>(n / 2, 1); chunk >= 1 && n > 0; chunk /= 2) {
      std::size_t at = 0;
      while (at + chunk <= count(r_.pslg)) {
        if (out_of_budget()) return any;
        if (attempt(remove(bare(r_.pslg), at, at + chunk)))
          any = true;
        else
          at += chunk;
      }
    }
    return any;
  }

  bool structural_pass() {
    bool any = false;
    // Hole points.
    any |= remove_chunks([](const Pslg& p) { return p.holes.size(); },
                         [](Pslg p, std::size_t f, std::size_t l) {
                           erase_range(p.holes, f, l);
                           return p;
                         });
    // Whole pieces: a hole's ring, a crack apart from the rest, isolated vertices.
    any |= remove_chunks(
        [](const Pslg& p) {
          const std::size_t n = detail::pieces(p).size();
          return n > 1 ? n : 0;
        },
        [](const Pslg& p, std::size_t f, std::size_t l) {
          const auto all = detail::pieces(p);
          std::vector<int> ids;
          for (std::size_t i = f; i < l; ++i) ids.insert(ids.end(), all[i].begin(), all[i].end());
          return detail::without_vertices(p, flags(p.vertices.size(), ids));
        });
    // Segments (cracks, interior constraints); those a boundary needs do not validate without it.
    any |= remove_chunks([](const Pslg& p) { return p.segments.size(); },
                         [](Pslg p, std::size_t f, std::size_t l) {
                           erase_range(p.segments, f, l);
                           return p;
                         });
    // Vertices of degree 2 spliced out: a polygon (outer boundary or a hole's)
    // loses a corner and stays closed.
    any |= remove_chunks([](const Pslg& p) { return detail::splice_candidates(p).size(); },
                         [](const Pslg& p, std::size_t f, std::size_t l) {
                           const auto c = detail::splice_candidates(p);
                           return detail::spliced(p, std::vector<int>(c.begin() + static_cast<long>(f), c.begin() + static_cast<long>(l)));
                         });
    // Vertices with their segments (a crack's tip, a junction).
    any |= remove_chunks([](const Pslg& p) { return p.vertices.size(); },
                         [](const Pslg& p, std::size_t f, std::size_t l) {
                           std::vector<char> drop(p.vertices.size(), 0);
                           std::fill(drop.begin() + static_cast<long>(f), drop.begin() + static_cast<long>(l), 1);
                           return detail::without_vertices(p, drop);
                         });
    return any;
  }

  // Simpler coordinates: scaled by a power of two (exact) to an extent between
  // 8 and 16 when far from it, then rounded to the coarsest power-of-two grid
  // that still fails (1 is among those tried: integer coordinates).
  bool coordinates() {
    bool any = false;
    const int e = detail::extent_exponent(r_.pslg);
    if (e < 2 || e > 6) {
      Pslg scaled = bare(r_.pslg);
      const int k = 4 - e;
      for (Point& v : scaled.vertices) v = {std::ldexp(v.x, k), std::ldexp(v.y, k)};
      for (Point& h : scaled.holes) h = {std::ldexp(h.x, k), std::ldexp(h.y, k)};
      any |= attempt(scaled, false);
    }
    const int top = detail::extent_exponent(r_.pslg);
    for (int g = top; g >= top - 10 && !out_of_budget(); --g) {
      auto c = detail::rounded(bare(r_.pslg), g);
      if (!c) break;  // already on this grid, so on every finer one
      if (attempt(*c, false)) {
        any = true;
        break;
      }
    }
    return any;
  }

  const std::function<bool(const Pslg&)>& still_fails_;
  ShrinkLimits limits_;
  Clock::time_point t0_;
  ShrinkResult r_;
};

}  // namespace

ShrinkResult shrink_pslg(const Pslg& start, const std::function<bool(const Pslg&)>& still_fails, const ShrinkLimits& limits) {
  return Greedy(start, still_fails, limits).run();
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
