// SPDX-License-Identifier: GPL-3.0-or-later
// Shrinking a failing input through the engine: RapidCheck's tree, then greedy edits.
#include "lepp/audit/shrink/shrink.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <vector>

#include "lepp/audit/run/parallel.h"
#include "lepp/validate.h"
#include "inputs/shrink_tree.h"
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

// still_fails on a candidate, where anything it throws counts as "does not
// fail the same way": the candidate is not kept and the best input so far
// stays. An exception must not escape: in a worker thread of parallel_for it
// would end the whole audit (std::terminate), losing every other finding.
bool fails_safely(const std::function<bool(const Pslg&)>& still_fails, const Pslg& candidate) {
  try {
    return still_fails(candidate);
  } catch (...) {
    return false;
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
  std::optional<Pslg> admissible(const Pslg& candidate, bool structural) const {
    auto v = validated(candidate);
    if (!v) return std::nullopt;
    if (structural ? size(*v) >= size(r_.pslg) : size(*v) > size(r_.pslg)) return std::nullopt;
    return v;
  }

  // Tries the candidates in order, up to limits.jobs engine runs at once, and keeps
  // the first that still fails: its index, or -1 when none does.
  int attempt_first(const std::vector<Pslg>& candidates, bool structural) {
    std::vector<std::optional<Pslg>> ok;
    ok.reserve(candidates.size());
    for (const Pslg& c : candidates) ok.push_back(admissible(c, structural));
    const std::size_t jobs = std::max<std::size_t>(1, limits_.jobs);
    std::size_t at = 0;
    while (at < ok.size()) {
      if (out_of_budget()) return -1;
      std::vector<std::size_t> batch;
      for (; at < ok.size() && batch.size() < jobs && r_.runs + batch.size() < limits_.max_runs; ++at)
        if (ok[at]) batch.push_back(at);
      if (batch.empty()) continue;
      std::vector<char> fails(batch.size(), 0);
      parallel_for(batch.size(), jobs, [&](std::size_t i) { fails[i] = fails_safely(still_fails_, *ok[batch[i]]) ? 1 : 0; });
      r_.runs += batch.size();
      for (std::size_t i = 0; i < batch.size(); ++i)
        if (fails[i]) {
          r_.pslg = std::move(*ok[batch[i]]);
          ++r_.steps;
          return static_cast<int>(batch[i]);
        }
    }
    return -1;
  }

  bool attempt(const Pslg& candidate, bool structural = true) { return attempt_first({candidate}, structural) == 0; }

  // Removes chunks of the items count() lists, halves first (a big input goes
  // in few runs), down to single items; after a kept removal the same position
  // is tried again, since the later items moved up. The next `jobs` positions are
  // tried at once.
  bool remove_chunks(const Count& count, const Remove& remove) {
    bool any = false;
    const std::size_t n = count(r_.pslg);
    const std::size_t jobs = std::max<std::size_t>(1, limits_.jobs);
    for (std::size_t chunk = std::max<std::size_t>(n / 2, 1); chunk >= 1 && n > 0; chunk /= 2) {
      std::size_t at = 0;
      while (at + chunk <= count(r_.pslg)) {
        if (out_of_budget()) return any;
        std::vector<Pslg> candidates;
        std::vector<std::size_t> positions;
        for (std::size_t p = at; p + chunk <= count(r_.pslg) && candidates.size() < jobs; p += chunk) {
          candidates.push_back(remove(bare(r_.pslg), p, p + chunk));
          positions.push_back(p);
        }
        const int kept = attempt_first(candidates, true);
        if (kept >= 0) {
          any = true;
          at = positions[static_cast<std::size_t>(kept)];
        } else {
          at = positions.back() + chunk;
        }
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
    std::vector<Pslg> grids;
    for (int g = top; g >= top - 10; --g) {
      auto c = detail::rounded(bare(r_.pslg), g);
      if (!c) break;  // already on this grid, so on every finer one
      grids.push_back(std::move(*c));
    }
    any |= attempt_first(grids, false) >= 0;  // the coarsest that still fails
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
  if (!input.shrink_tree) return shrink_pslg(input.pslg, still_fails, limits);
  ShrinkResult r;
  r.pslg = input.pslg;
  const auto t0 = Clock::now();
  rc::Shrinkable<Pslg> cur = input.shrink_tree->root;
  const std::size_t jobs = std::max<std::size_t>(1, limits.jobs);
  bool progress = true;
  while (progress) {
    progress = false;
    auto shrinks = cur.shrinks();
    bool exhausted = false;
    while (!exhausted && !progress) {
      if (r.runs >= limits.max_runs || std::chrono::duration<double>(Clock::now() - t0).count() > limits.max_seconds)
        return r;
      // The next `jobs` shrinks that validate (made here, on this thread), run at once; the first still failing is kept.
      std::vector<rc::Shrinkable<Pslg>> batch;
      std::vector<Pslg> values;
      while (batch.size() < jobs && r.runs + batch.size() < limits.max_runs) {
        auto s = shrinks.next();
        if (!s) {
          exhausted = true;
          break;
        }
        std::optional<Pslg> v;
        try {
          v = validated(s->value());
        } catch (const std::exception&) {
          v.reset();
        }
        if (!v) continue;
        batch.push_back(*s);
        values.push_back(std::move(*v));
      }
      if (batch.empty()) break;
      std::vector<char> fails(batch.size(), 0);
      parallel_for(batch.size(), jobs, [&](std::size_t i) { fails[i] = fails_safely(still_fails, values[i]) ? 1 : 0; });
      r.runs += batch.size();
      for (std::size_t i = 0; i < batch.size(); ++i)
        if (fails[i]) {
          r.pslg = std::move(values[i]);
          ++r.steps;
          cur = batch[i];
          progress = true;
          break;
        }
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
