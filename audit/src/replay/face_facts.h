// SPDX-License-Identifier: GPL-3.0-or-later
// What the replay's searches ask of a face again and again: which of its edges
// are longest (ties included) and whether it may be bad. The search backwards
// along the Lepp tree (Replayer::bad_reaching) walks, where no bad triangle is
// near, much of the mesh at every step, and the answers are exact predicates
// (GMP near ties): on a fuzzer's 118,000-vertex trace they were four fifths of
// the replay. Each answer is a function of the face's three points (in order)
// and its region, under the reading of the moment (lengths within rounding as
// ties or not; the threshold within rounding or not), so it is kept per face
// handle with the vertices and region it was computed for. CGAL reuses a face
// in place when it splits or flips it, and reuses a freed face's slot: an entry
// whose face no longer has those vertices and region starts afresh. An entry
// is never freed: a face's is reused for as long as the face lives, and faces
// are rarely freed while a mesh is refined.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "triangulation.h"  // reference/src: the exact engine's CDT

namespace lepp::audit::replay_detail {

class FaceFacts {
  using FH = reference::detail::FH;
  using VH = reference::detail::VH;

 public:
  static constexpr std::int8_t kUnknown = -1;
  struct Facts {
    const void* face = nullptr;  // the face the entry is for
    std::array<VH, 3> vertices;
    int region = 0;
    // Per reading (index 0: exact, 1: within rounding): a bit per longest
    // edge, and bad or not; kUnknown until asked.
    std::array<std::int8_t, 2> longest{kUnknown, kUnknown};
    std::array<std::int8_t, 2> bad{kUnknown, kUnknown};
    std::uint64_t walk = 0;  // the last walk that reached the face (new_walk)
  };

  FaceFacts() { add(); }  // entry 0: no face's
  // A copy holds another triangulation's faces: it starts empty.
  FaceFacts(const FaceFacts&) : FaceFacts() {}
  FaceFacts& operator=(const FaceFacts&) {
    chunks_.clear();
    size_ = 0;
    add();
    return *this;
  }

  // f's entry, valid for its vertices and region now. Found through the face
  // (FaceInfo::facts): a copied FaceInfo points at another face's entry, whose
  // owner then differs, and f gets its own.
  Facts& of(FH f) {
    std::uint32_t& slot = f->info().facts;
    const std::array<VH, 3> now{f->vertex(0), f->vertex(1), f->vertex(2)};
    if (slot == 0 || slot >= size_ || entry(slot).face != &*f) {
      slot = add();
    } else if (Facts& e = entry(slot); e.vertices == now && e.region == f->info().region) {
      return e;
    } else {
      ++restarts_;
    }
    Facts& e = entry(slot) = Facts{};
    e.face = &*f;
    e.vertices = now;
    e.region = f->info().region;
    return e;
  }

  // A mark for one walk over faces: a face is reached in it when its entry's
  // walk equals the mark.
  std::uint64_t new_walk() { return ++walks_; }

  // Entries that were found stale and started afresh (tests: the in-place
  // reuse is seen).
  std::int64_t restarts() const { return restarts_; }

 private:
  // Entries in chunks, which never move as others are added (a walk holds them).
  static constexpr std::uint32_t kChunkBits = 8;
  std::vector<std::unique_ptr<Facts[]>> chunks_;
  std::uint32_t size_ = 0;
  std::uint64_t walks_ = 0;
  std::int64_t restarts_ = 0;

  Facts& entry(std::uint32_t i) { return chunks_[i >> kChunkBits][i & ((1u << kChunkBits) - 1)]; }
  std::uint32_t add() {
    if ((size_ & ((1u << kChunkBits) - 1)) == 0) chunks_.push_back(std::make_unique<Facts[]>(1u << kChunkBits));
    return size_++;
  }
};

}  // namespace lepp::audit::replay_detail
