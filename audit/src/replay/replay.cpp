// SPDX-License-Identifier: GPL-3.0-or-later
// lepp::audit::Replay (lepp/audit/replay.h): the public face of the replay,
// each call handed to its state and searches (replayer.h).
#include "lepp/audit/replay.h"

#include "replayer.h"

namespace lepp::audit {

struct Replay::Impl : replay_detail::Replayer {
  using Replayer::Replayer;
};

const char* to_string(CentroidReading reading) { return reading == CentroidReading::Area ? "area" : "vertex"; }

const char* to_string(MeshReading reading) {
  switch (reading) {
    case MeshReading::Exact: return "exact";
    case MeshReading::NoFlips: return "no-flips";
    case MeshReading::NoFlipsButSplits: return "no-flips-but-splits";
    case MeshReading::DoubleIncircle: return "double-incircle";
    case MeshReading::FloatPoints: return "float-points";
    case MeshReading::TiesKept: return "ties-kept";
    case MeshReading::FloatInput: return "float-input";
  }
  return "?";
}

double nearest_float(double x) {
  // Through a volatile: GCC 12 (-O2) drops the round trip when it vectorizes a
  // point's two coordinates together.
  volatile float f = static_cast<float>(x);
  return f;
}

Replay::Replay(const Pslg& pslg, const ReplayRules& rules) : impl_(std::make_unique<Impl>(pslg, rules)) {}
Replay::~Replay() = default;
bool Replay::match(const Point& p, ReplayChoice& choice) { return impl_->match(p, choice); }
void Replay::insert(const Point& p, const ReplayChoice& choice) { impl_->insert(p, choice); }
void Replay::allow(Deviation variant) { impl_->allow(variant); }
std::vector<ReplayChoice> Replay::all_choices(const Point& p, std::size_t limit, std::size_t& total) {
  return impl_->all_choices(p, limit, total);
}
DeviationMatch Replay::diagnose(const Point& p) const { return impl_->diagnose(p); }
Theorem2Check Replay::theorem2(const ReplayChoice& choice) const { return impl_->theorem2(choice); }
Mesh Replay::mesh() const { return replay_detail::extract_mesh(impl_->tr); }
std::size_t Replay::steiner_points() const { return impl_->tr.vertex.size() - impl_->tr.input_vertices; }
std::int64_t Replay::cocircular_ties() const { return impl_->tr.cocircular_ties; }
std::int64_t Replay::cocircular_flips() const { return impl_->cocircular_flips_; }
bool Replay::cocircular_search_exhausted() const { return impl_->search_exhausted_; }

}  // namespace lepp::audit
