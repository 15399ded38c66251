// SPDX-License-Identifier: GPL-3.0-or-later
// The queue of bad triangles and its processing orders (ALGORITHM.md section 7):
// one small interface (push an insertion's batch, pop the next) and one policy
// per order, so that the refinement loop does not know which order runs.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

#include "lepp/refine.h"
#include "predicates.h"
#include "ring_queue.h"
#include "tri_mesh.h"

namespace lepp::fast {

// A queued triangle: its slot and the slot's stamp when it was queued. Slots
// are rewritten in place and every rewrite destroys the triangle that was
// there, so "t remains in tau" iff the stamp is unchanged.
struct Item {
  int tri;
  std::uint32_t stamp;
};
inline bool still_there(const TriMesh& m, const Item& it) { return m.stamp[static_cast<std::size_t>(it.tri)] == it.stamp; }

// A member of a batch: the triangle's key (its vertex ids sorted ascending) and,
// for the flip order, its place in the insertion's creation order.
struct Keyed {
  int k[3];
  Item item;
  int created = 0;
};

// Three ids in ascending order (a sorting network).
inline void sort3(int& a, int& b, int& c) {
  if (a > b) std::swap(a, b);
  if (b > c) std::swap(b, c);
  if (a > b) std::swap(a, b);
}

// k becomes triangle ti's key and item, in its place.
inline void set_keyed(Keyed& k, const TriMesh& m, int ti) {
  const FTri& f = m.t(ti);
  int a = f.v(0), b = f.v(1), c = f.v(2);
  sort3(a, b, c);
  k.k[0] = a, k.k[1] = b, k.k[2] = c;
  k.item.tri = ti, k.item.stamp = m.stamp[static_cast<std::size_t>(ti)];
  k.created = 0;
}
inline Keyed keyed(const TriMesh& m, int ti) {
  Keyed k;
  set_keyed(k, m, ti);
  return k;
}
// keyed(m, ti) appended to `batch`, made in its place: a Keyed made apart and
// copied in was stored in 4-byte parts and read back in wider ones at once, a
// stalled store forwarding (issue 40: about 40 % of the star walk's time).
inline void append_keyed(std::vector<Keyed>& batch, const TriMesh& m, int ti) { set_keyed(batch.emplace_back(), m, ti); }
inline bool key_less(const Keyed& x, const Keyed& y) {
  if (x.k[0] != y.k[0]) return x.k[0] < y.k[0];
  if (x.k[1] != y.k[1]) return x.k[1] < y.k[1];
  return x.k[2] < y.k[2];
}
// key_less as a type for std::sort, which then inlines it: given the function, the
// sort of each insertion's batch called it through a pointer (std::__insertion_sort
// was 1.2 % of a 10^6 refinement's samples).
struct KeyLess {
  bool operator()(const Keyed& x, const Keyed& y) const { return key_less(x, y); }
};

// SplitMix64 (ALGORITHM.md section 7 spells it out; the reference engine has its own).
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : x_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (x_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }

 private:
  std::uint64_t x_;
};

class BadQueue {
 public:
  BadQueue(QueueOrder order, std::uint64_t seed, const TriMesh& mesh)
      : order_(order), rng_(seed), heap_(Worse{&mesh}), mesh_(mesh) {}

  QueueOrder order() const { return order_; }

  // Adds the initial queue or an insertion's batch (in any order: the policy
  // sorts it; `created` must be set for the flip order's batches).
  void push(std::vector<Keyed>& batch, bool initial) {
    switch (order_) {
      case QueueOrder::Fifo:
      case QueueOrder::Batch:  // runs in rounds (batch_rounds.h), not through this queue
        std::sort(batch.begin(), batch.end(), KeyLess{});
        for (const Keyed& k : batch) ring_.push_back(k.item);
        return;
      case QueueOrder::Lifo:
        std::sort(batch.begin(), batch.end(), KeyLess{});
        for (auto it = batch.rbegin(); it != batch.rend(); ++it) ring_.push_front(it->item);
        return;
      case QueueOrder::Flip:
        if (initial)
          std::sort(batch.begin(), batch.end(), KeyLess{});
        else
          std::sort(batch.begin(), batch.end(), [](const Keyed& x, const Keyed& y) { return x.created < y.created; });
        for (const Keyed& k : batch) ring_.push_back(k.item);
        return;
      case QueueOrder::Random:
        std::sort(batch.begin(), batch.end(), KeyLess{});
        for (std::size_t i = batch.size(); i-- > 1;) std::swap(batch[i], batch[rng_.next() % (i + 1)]);
        for (const Keyed& k : batch) ring_.push_back(k.item);
        return;
      case QueueOrder::SmallestAngle:
        for (const Keyed& k : batch) heap_.push(ranked(k));
        return;
    }
  }

  bool empty() const { return order_ == QueueOrder::SmallestAngle ? heap_.empty() : ring_.empty(); }

  Item pop() {
    if (order_ == QueueOrder::SmallestAngle) {
      Item it = heap_.top().item;
      heap_.pop();
      return it;
    }
    Item it = ring_.front();
    ring_.pop_front();
    prefetch_ahead();
    return it;
  }

 private:
  // A heap entry: the key, an approximation of sin^2 of the smallest angle and
  // a bound on its error (infinite where the bound does not hold: exact compare).
  struct Ranked {
    double sin2, err;
    int k[3];
    Item item;
  };
  // Heap order: x below y iff y comes first (smaller sin^2, then smaller key).
  struct Worse {
    const TriMesh* m;
    bool operator()(const Ranked& x, const Ranked& y) const { return first(y, x); }
    bool first(const Ranked& x, const Ranked& y) const {
      if (x.k[0] == y.k[0] && x.k[1] == y.k[1] && x.k[2] == y.k[2]) return false;
      if (x.sin2 + x.err < y.sin2 - y.err) return true;
      if (y.sin2 + y.err < x.sin2 - x.err) return false;
      const Point a[3] = {m->p(x.k[0]), m->p(x.k[1]), m->p(x.k[2])};
      const Point b[3] = {m->p(y.k[0]), m->p(y.k[1]), m->p(y.k[2])};
      const int s = detail::compare_sin2_exact(a, b);
      if (s != 0) return s < 0;
      if (x.k[0] != y.k[0]) return x.k[0] < y.k[0];
      if (x.k[1] != y.k[1]) return x.k[1] < y.k[1];
      return x.k[2] < y.k[2];
    }
  };

  // sin^2 = cross^2 / M, M the largest product of two squared edge lengths (the
  // two longest edges). Each quantity is a short tree of roundings of exact
  // inputs: cross is off by at most 3u |pc| (pc = |c1| + |c2|), M by 7u M, so the
  // ratio by at most about 14u pc^2 / M; 64u leaves room for the rest.
  Ranked ranked(const Keyed& k) const {
    const Point &a = mesh_.p(k.k[0]), &b = mesh_.p(k.k[1]), &c = mesh_.p(k.k[2]);
    const double ux = b.x - a.x, uy = b.y - a.y, vx = c.x - a.x, vy = c.y - a.y, wx = c.x - b.x, wy = c.y - b.y;
    const double c1 = ux * vy, c2 = uy * vx, cross = c1 - c2, pc = std::fabs(c1) + std::fabs(c2);
    const double la = ux * ux + uy * uy, lb = vx * vx + vy * vy, lc = wx * wx + wy * wy;
    const double m = std::max(std::max(la * lb, la * lc), lb * lc);
    Ranked r{0, std::numeric_limits<double>::infinity(), {k.k[0], k.k[1], k.k[2]}, k.item};
    const double pc2 = pc * pc;
    if (pc2 >= detail::kTiny && pc2 <= detail::kHuge && m >= detail::kTiny && m <= detail::kHuge) {
      r.sin2 = cross * cross / m;
      r.err = 64 * detail::kUnit * (pc2 / m);
    }
    return r;
  }

  // The queue runs far behind the insertions (fifo): its triangles and their
  // points are cold in cache. Fetch the next items' while this one is processed:
  // the stamps 8 entries ahead, the live triangles 4 ahead, their points 2 ahead,
  // and 1 ahead the triangle across the cached longest edge (the Lepp's first step).
  // Always inlined: GCC finds a function whose only effect is a prefetch pure and
  // deletes the call, prefetches and all (until issue 40's fifth step this function,
  // out of line, compiled to nothing: every distance tried before measured no prefetch).
  [[gnu::always_inline]] void prefetch_ahead() const {
    if (ring_.size() > 8) __builtin_prefetch(&mesh_.stamp[static_cast<std::size_t>(ring_[8].tri)]);
    if (ring_.size() > 4 && still_there(mesh_, ring_[4])) __builtin_prefetch(&mesh_.t(ring_[4].tri));
    if (ring_.size() > 2 && still_there(mesh_, ring_[2])) {
      const FTri& f = mesh_.t(ring_[2].tri);
      for (int i = 0; i < 3; ++i) __builtin_prefetch(&mesh_.p(f.v(i)));
    }
    if (ring_.size() > 1 && still_there(mesh_, ring_[1])) {
      const FTri& f = mesh_.t(ring_[1].tri);
      if (const int l = f.longest(); l >= 0 && f.nbr[l] >= 0) __builtin_prefetch(&mesh_.t(nbr_tri(f.nbr[l])));
    }
  }

  QueueOrder order_;
  SplitMix64 rng_;
  RingQueue<Item> ring_;  // every order but smallest-angle
  std::priority_queue<Ranked, std::vector<Ranked>, Worse> heap_;
  const TriMesh& mesh_;
};

}  // namespace lepp::fast
