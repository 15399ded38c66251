// SPDX-License-Identifier: GPL-3.0-or-later
// Where violations go (the per-reason listing cap, the one-group filter) and the index's small queries.
#include "certification.h"

#include <algorithm>

#include "exact.h"
#include "index/index_limits.h"

namespace lepp::certify {

constexpr std::size_t kReasons = static_cast<std::size_t>(Reason::AreaAboveBound) + 1;

Certification::Certification(const Pslg& pslg, const Mesh& mesh, const Options& opts, Report& out, std::optional<Check> group)
    : options(opts), report(out), index(pslg, mesh), only(group) {
  check_index_limits(mesh.vertices.size(), mesh.triangles.size());
  report.count_by_reason.assign(kReasons, 0);
  report.min_angle_deg = options.min_angle_deg;
}

void Certification::add(Violation v) {
  if (only && check_of(v.reason) != *only) return;  // another group's: not this run's business
  std::size_t r = static_cast<std::size_t>(v.reason);
  if (report.count_by_reason[r]++ < options.max_listed_per_reason) {
    for (int id : v.vertices)
      if (id >= 0 && static_cast<std::size_t>(id) < index.mesh.vertices.size() && v.points.size() < v.vertices.size())
        v.points.push_back(index.P(id));
    report.violations.push_back(std::move(v));
  }
}

std::string MeshIndex::tri_text(std::size_t t) const {
  const Tri& x = T(t);
  return fmt::format("triangle {} ({} {} {}: {} {} {})", t, x[0], x[1], x[2], pt(P(x[0])), pt(P(x[1])), pt(P(x[2])));
}

std::pair<const MeshIndex::Half*, const MeshIndex::Half*> MeshIndex::halves_on(int v, int w) const {
  if (v > w) std::swap(v, w);
  const Half* first = halves.data() + half_begin[static_cast<std::size_t>(v)];
  const Half* last = halves.data() + half_begin[static_cast<std::size_t>(v) + 1];
  auto by_other = [](const Half& x, const Half& y) { return x.other < y.other; };
  return std::equal_range(first, last, Half(w, 0, false), by_other);
}

bool MeshIndex::adjacent(int v, int w) const {
  if (w > v) {
    const auto [first, last] = halves_on(v, w);
    return first != last;
  }
  const auto first = lower.begin() + lower_begin[static_cast<std::size_t>(v)], last = lower.begin() + lower_begin[static_cast<std::size_t>(v) + 1];
  return std::binary_search(first, last, w);
}

std::vector<int> MeshIndex::neighbors(int v) const {
  const std::size_t u = static_cast<std::size_t>(v);
  std::vector<int> out(lower.begin() + lower_begin[u], lower.begin() + lower_begin[u + 1]);
  each_edge_up_from(u, [&out](int b, std::size_t) { out.push_back(b); });
  return out;
}

bool MeshIndex::longer(int a, int b, int c, int d) const {
  const int s = exact::compare_squared_length(P(a), P(b), P(c), P(d));
  if (s != 0) return s > 0;
  const int e0 = std::min(a, b), e1 = std::max(a, b), f0 = std::min(c, d), f1 = std::max(c, d);
  return e0 != f0 ? e0 < f0 : e1 < f1;
}

}  // namespace lepp::certify
