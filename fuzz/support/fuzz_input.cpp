// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind fuzz_input.h: the structured input of fuzz_refine, fuzz_differential
// and fuzz_cdt.
#include "fuzz_input.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>
#include <string>

#include <fmt/format.h>
#include <fuzzer/FuzzedDataProvider.h>

#include "lepp/engines/registry.h"
#include "lepp/io.h"
#include "lepp/validate.h"

namespace lepp::fuzz {

const std::vector<double>& scales() {
  static const std::vector<double> s = {1.0, 0.125, 1.0 / 1024, 64.0, 0.1, 1e-3};
  return s;
}

namespace {

// Mirrors FuzzedDataProvider::ConsumeIntegralInRange: a value in [lo, hi]
// takes as many bytes as hi - lo needs, read from the end of the data, most
// significant first. encode() records them in reading order and reverses.
class Writer {
 public:
  void put(int value, int lo, int hi) {
    const std::uint64_t range = static_cast<std::uint64_t>(hi - lo);
    std::uint64_t v = static_cast<std::uint64_t>(std::clamp(value, lo, hi) - lo);
    int bytes = 0;
    while (bytes < 8 && (range >> (8 * bytes)) > 0) ++bytes;
    for (int k = bytes - 1; k >= 0; --k) read_order_.push_back(static_cast<std::uint8_t>(v >> (8 * k)));
  }
  std::vector<std::uint8_t> bytes() const { return {read_order_.rbegin(), read_order_.rend()}; }

 private:
  std::vector<std::uint8_t> read_order_;
};

template <class Sink>
void visit(FuzzInput& in, Sink&& field) {
  field(in.method, 0, 1);
  field(in.engine, 0, 1);
  field(in.order, 0, 1);
  field(in.theta_tenths, 100, 360);
  field(in.grid, 2, FuzzInput::kMaxGrid);
  field(in.scale, 0, static_cast<int>(scales().size()) - 1);
}

long long orient(const GridPoint& a, const GridPoint& b, const GridPoint& c) {
  return static_cast<long long>(b.x - a.x) * (c.y - a.y) - static_cast<long long>(b.y - a.y) * (c.x - a.x);
}
bool same(const GridPoint& a, const GridPoint& b) { return a.x == b.x && a.y == b.y; }
// p strictly inside segment ab (exact on the grid).
bool inside(const GridPoint& p, const GridPoint& a, const GridPoint& b) {
  if (orient(a, b, p) != 0 || same(p, a) || same(p, b)) return false;
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}
bool cross_properly(const GridPoint& a, const GridPoint& b, const GridPoint& c, const GridPoint& d) {
  auto sgn = [](long long v) { return (v > 0) - (v < 0); };
  return sgn(orient(a, b, c)) * sgn(orient(a, b, d)) < 0 && sgn(orient(c, d, a)) * sgn(orient(c, d, b)) < 0;
}

}  // namespace

FuzzInput decode(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider fdp(data, size);
  FuzzInput in;
  visit(in, [&](int& v, int lo, int hi) { v = fdp.ConsumeIntegralInRange<int>(lo, hi); });
  const int nv = fdp.ConsumeIntegralInRange<int>(3, FuzzInput::kMaxVertices);
  for (int i = 0; i < nv; ++i) {
    GridPoint p;
    p.x = fdp.ConsumeIntegralInRange<int>(0, in.grid);
    p.y = fdp.ConsumeIntegralInRange<int>(0, in.grid);
    in.vertices.push_back(p);
  }
  const int ns = fdp.ConsumeIntegralInRange<int>(0, FuzzInput::kMaxSegments);
  for (int i = 0; i < ns; ++i) {
    GridSegment s;
    s.a = fdp.ConsumeIntegralInRange<int>(0, nv - 1);
    s.b = fdp.ConsumeIntegralInRange<int>(0, nv - 1);
    in.segments.push_back(s);
  }
  const int nh = fdp.ConsumeIntegralInRange<int>(0, FuzzInput::kMaxHoles);
  for (int i = 0; i < nh; ++i) {
    GridPoint p;
    p.x = fdp.ConsumeIntegralInRange<int>(0, 2 * in.grid);
    p.y = fdp.ConsumeIntegralInRange<int>(0, 2 * in.grid);
    in.holes.push_back(p);
  }
  // Leftover bytes of an older input would be read as the fields below: they
  // count only after this marker (1 in 256 older inputs with a leftover byte change).
  if (fdp.ConsumeIntegralInRange<int>(0, 255) != FuzzInput::kPrecisionMarker) return in;
  in.offset = fdp.ConsumeIntegralInRange<int>(0, FuzzInput::kMaxOffset);
  const int nj = fdp.ConsumeIntegralInRange<int>(0, FuzzInput::kMaxJitters);
  for (int i = 0; i < nj; ++i) {
    UlpJitter j;
    j.vertex = fdp.ConsumeIntegralInRange<int>(0, nv - 1);
    j.dx = fdp.ConsumeIntegralInRange<int>(-FuzzInput::kMaxUlps, FuzzInput::kMaxUlps);
    j.dy = fdp.ConsumeIntegralInRange<int>(-FuzzInput::kMaxUlps, FuzzInput::kMaxUlps);
    in.jitters.push_back(j);
  }
  return in;
}

std::vector<std::uint8_t> encode(const FuzzInput& input) {
  FuzzInput in = input;
  Writer w;
  visit(in, [&](int& v, int lo, int hi) { w.put(v, lo, hi); });
  const int nv = std::clamp(static_cast<int>(in.vertices.size()), 3, FuzzInput::kMaxVertices);
  w.put(nv, 3, FuzzInput::kMaxVertices);
  for (int i = 0; i < nv; ++i) {
    GridPoint p = i < static_cast<int>(in.vertices.size()) ? in.vertices[static_cast<std::size_t>(i)] : GridPoint{};
    w.put(p.x, 0, in.grid);
    w.put(p.y, 0, in.grid);
  }
  const int ns = std::min(static_cast<int>(in.segments.size()), FuzzInput::kMaxSegments);
  w.put(ns, 0, FuzzInput::kMaxSegments);
  for (int i = 0; i < ns; ++i) {
    w.put(in.segments[static_cast<std::size_t>(i)].a, 0, nv - 1);
    w.put(in.segments[static_cast<std::size_t>(i)].b, 0, nv - 1);
  }
  const int nh = std::min(static_cast<int>(in.holes.size()), FuzzInput::kMaxHoles);
  w.put(nh, 0, FuzzInput::kMaxHoles);
  for (int i = 0; i < nh; ++i) {
    w.put(in.holes[static_cast<std::size_t>(i)].x, 0, 2 * in.grid);
    w.put(in.holes[static_cast<std::size_t>(i)].y, 0, 2 * in.grid);
  }
  if (in.offset == 0 && in.jitters.empty()) return w.bytes();  // as before the fields existed
  w.put(FuzzInput::kPrecisionMarker, 0, 255);
  w.put(in.offset, 0, FuzzInput::kMaxOffset);
  const int nj = std::min(static_cast<int>(in.jitters.size()), FuzzInput::kMaxJitters);
  w.put(nj, 0, FuzzInput::kMaxJitters);
  for (int i = 0; i < nj; ++i) {
    const UlpJitter& j = in.jitters[static_cast<std::size_t>(i)];
    w.put(j.vertex, 0, nv - 1);
    w.put(j.dx, -FuzzInput::kMaxUlps, FuzzInput::kMaxUlps);
    w.put(j.dy, -FuzzInput::kMaxUlps, FuzzInput::kMaxUlps);
  }
  return w.bytes();
}

bool precision_campaign() {
  const char* env = std::getenv("LEPP_FUZZ_PRECISION");
  return env != nullptr && std::string(env) == "1";
}

bool in_precision_family(const FuzzInput& input) { return input.offset > 0 || !input.jitters.empty(); }

void add_cluster(FuzzInput& in, int vertex, int copies, const std::function<std::pair<int, int>(int)>& ulps) {
  if (vertex < 0 || vertex >= static_cast<int>(in.vertices.size())) return;
  for (int k = 0; k < copies && static_cast<int>(in.vertices.size()) < FuzzInput::kMaxVertices &&
                  static_cast<int>(in.jitters.size()) < FuzzInput::kMaxJitters;
       ++k) {
    in.vertices.push_back(in.vertices[static_cast<std::size_t>(vertex)]);
    const auto [dx, dy] = ulps(k);
    in.jitters.push_back({static_cast<int>(in.vertices.size()) - 1, std::clamp(dx, -FuzzInput::kMaxUlps, FuzzInput::kMaxUlps),
                          std::clamp(dy, -FuzzInput::kMaxUlps, FuzzInput::kMaxUlps)});
  }
}

void apply_environment(FuzzInput& input) {
  if (precision_campaign() && !in_precision_family(input) && !input.vertices.empty()) {
    // Two to four copies of one vertex. The x moves (-4..4 ulps) differ from copy to copy, so
    // no two copies coincide, and a copy with no move at all is moved one ulp in x.
    const int v = input.theta_tenths % static_cast<int>(input.vertices.size());
    add_cluster(input, v, 2 + input.grid % 3, [&](int k) {
      const int dx = (k + input.theta_tenths) % 9 - 4, dy = (3 * k + input.grid) % 9 - 4;
      return std::pair<int, int>{dx == 0 && dy == 0 ? 1 : dx, dy};
    });
  }
  if (const char* m = std::getenv("LEPP_FUZZ_METHOD"))
    input.method = lepp::engines::parse_method(m).value_or(Method::Centroid) == Method::Midpoint ? 1 : 0;
  if (const char* band = std::getenv("LEPP_FUZZ_THETA")) {
    double lo = 10, hi = 36;
    if (std::sscanf(band, "%lf:%lf", &lo, &hi) == 2 && lo <= hi) {
      const int lo10 = static_cast<int>(lo * 10 + 0.5), hi10 = static_cast<int>(hi * 10 + 0.5);
      input.theta_tenths = lo10 + (input.theta_tenths - 100) % (hi10 - lo10 + 1);
    }
  }
}

double theta_deg(const FuzzInput& input) { return input.theta_tenths / 10.0; }

Pslg to_pslg(const FuzzInput& in) {
  const double s = scales()[static_cast<std::size_t>(in.scale)];
  Pslg pslg;
  pslg.source = "<fuzz>";
  const double offset = in.offset > 0 ? std::ldexp(1.0, in.offset - 1) : 0.0;
  for (const GridPoint& p : in.vertices) pslg.vertices.push_back({p.x * s + offset, p.y * s + offset});
  auto step = [](double x, int k) {
    for (; k > 0; --k) x = std::nextafter(x, HUGE_VAL);
    for (; k < 0; ++k) x = std::nextafter(x, -HUGE_VAL);
    return x;
  };
  for (const UlpJitter& j : in.jitters) {
    if (j.vertex < 0 || j.vertex >= static_cast<int>(pslg.vertices.size())) continue;
    Point& p = pslg.vertices[static_cast<std::size_t>(j.vertex)];
    p = {step(p.x, j.dx), step(p.y, j.dy)};
  }
  std::set<std::pair<int, int>> seen;  // by the first vertex with the same coordinates
  auto first_with = [&](int v) {
    for (int u = 0; u < v; ++u)
      if (same(in.vertices[static_cast<std::size_t>(u)], in.vertices[static_cast<std::size_t>(v)])) return u;
    return v;
  };
  std::vector<GridSegment> kept;
  for (const GridSegment& seg : in.segments) {
    const GridPoint &a = in.vertices[static_cast<std::size_t>(seg.a)], &b = in.vertices[static_cast<std::size_t>(seg.b)];
    if (same(a, b)) continue;
    if (!seen.insert(std::minmax(first_with(seg.a), first_with(seg.b))).second) continue;
    bool ok = true;
    for (const GridPoint& p : in.vertices) ok = ok && !inside(p, a, b);
    for (const GridSegment& k : kept)
      ok = ok && !cross_properly(a, b, in.vertices[static_cast<std::size_t>(k.a)], in.vertices[static_cast<std::size_t>(k.b)]);
    if (!ok) continue;
    kept.push_back(seg);
    pslg.segments.push_back({seg.a, seg.b, 0});
  }
  for (const GridPoint& h : in.holes) pslg.holes.push_back({h.x * 0.5 * s + offset, h.y * 0.5 * s + offset});
  std::vector<std::string> warnings;
  return validate(pslg, warnings);
}

std::optional<Pslg> valid_pslg(const FuzzInput& input) {
  try {
    return to_pslg(input);
  } catch (const InputError&) {
    return std::nullopt;
  }
}

RefineOptions options_of(const FuzzInput& in) {
  RefineOptions o;
  o.min_angle_deg = theta_deg(in);
  o.method = in.method == 1 ? Method::Midpoint : Method::Centroid;
  o.order = in.order == 1 ? QueueOrder::Lifo : QueueOrder::Fifo;
  // LEPP_FUZZ_ORDER=batch (any order's name) fuzzes one order whatever the input says.
  if (const char* order = std::getenv("LEPP_FUZZ_ORDER")) o.order = lepp::engines::parse_order(order).value_or(o.order);
  return o;
}

void mutate(FuzzInput& in, std::mt19937& rng) {
  auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  auto random_point = [&] { return GridPoint{pick(0, in.grid), pick(0, in.grid)}; };
  const int nv = static_cast<int>(in.vertices.size());
  // The precision campaign makes every other edit a cluster or an offset (cases 12, 13).
  switch (precision_campaign() && pick(0, 1) ? 12 : pick(0, 13)) {
    case 0:
    case 1:
      if (nv > 0) {  // nudge a vertex
        GridPoint& p = in.vertices[static_cast<std::size_t>(pick(0, nv - 1))];
        (pick(0, 1) ? p.x : p.y) += pick(0, 1) ? 1 : -1;
        p.x = std::clamp(p.x, 0, in.grid), p.y = std::clamp(p.y, 0, in.grid);
      }
      break;
    case 2:
      if (nv < FuzzInput::kMaxVertices) in.vertices.push_back(random_point());
      break;
    case 3:
      if (nv > 3) {  // remove a vertex and the segments on it
        const int v = pick(0, nv - 1);
        in.vertices.erase(in.vertices.begin() + v);
        std::vector<UlpJitter> moved;
        for (UlpJitter j : in.jitters)
          if (j.vertex != v) j.vertex -= j.vertex > v, moved.push_back(j);
        in.jitters = moved;
        std::vector<GridSegment> kept;
        for (GridSegment s : in.segments) {
          if (s.a == v || s.b == v) continue;
          s.a -= s.a > v, s.b -= s.b > v;
          kept.push_back(s);
        }
        in.segments = kept;
      }
      break;
    case 4:
    case 5:
      if (nv > 1 && in.segments.size() < FuzzInput::kMaxSegments) {  // consecutive vertices make polygons
        const int a = pick(0, nv - 1);
        const int b = pick(0, 2) ? (a + 1) % nv : pick(0, nv - 1);
        in.segments.push_back({a, b});
      }
      break;
    case 6:
      if (!in.segments.empty()) in.segments.erase(in.segments.begin() + pick(0, static_cast<int>(in.segments.size()) - 1));
      break;
    case 7:
      if (in.holes.size() < FuzzInput::kMaxHoles && pick(0, 1)) {
        in.holes.push_back({pick(0, 2 * in.grid), pick(0, 2 * in.grid)});
      } else if (!in.holes.empty()) {
        in.holes.pop_back();
      }
      break;
    case 8:
      in.theta_tenths = std::clamp(in.theta_tenths + (pick(0, 1) ? pick(-10, 10) : pick(-100, 100)), 100, 360);
      break;
    case 9:
      if (pick(0, 1)) in.method ^= 1; else if (pick(0, 1)) in.order ^= 1; else in.engine ^= 1;
      break;
    case 10: {  // refine or coarsen the grid, keeping the shape
      const int grid = std::clamp(pick(0, 1) ? in.grid * 2 : in.grid / 2, 2, FuzzInput::kMaxGrid);
      for (GridPoint& p : in.vertices) p.x = std::min(p.x * grid / in.grid, grid), p.y = std::min(p.y * grid / in.grid, grid);
      for (GridPoint& h : in.holes) h.x = std::min(h.x * grid / in.grid, 2 * grid), h.y = std::min(h.y * grid / in.grid, 2 * grid);
      in.grid = grid;
      break;
    }
    case 12:
    case 13:
      if (nv > 0 && pick(0, 3) == 0) {  // a large offset: coordinates far from the origin, few bits left
        in.offset = pick(0, 1) ? pick(20, FuzzInput::kMaxOffset) : 0;
      } else if (nv > 0) {  // a cluster: copies of one vertex, each a few ulps from it
        const int v = pick(0, nv - 1), copies = pick(1, 4);  // in this order: the draws stay as they were
        add_cluster(in, v, copies, [&](int) {
          return std::pair<int, int>{pick(-FuzzInput::kMaxUlps, FuzzInput::kMaxUlps), pick(-FuzzInput::kMaxUlps, FuzzInput::kMaxUlps)};
        });
      }
      break;
    default:
      in.scale = pick(0, static_cast<int>(scales().size()) - 1);
      break;
  }
}

std::string describe(const FuzzInput& in) {
  std::string s = fmt::format("method={} theta={} order={} engine={} grid={} scale={} vertices=[",
                              to_string(in.method ? Method::Midpoint : Method::Centroid), theta_deg(in),
                              to_string(in.order ? QueueOrder::Lifo : QueueOrder::Fifo),
                              lepp::engines::to_string(in.engine ? lepp::engines::Engine::Reference : lepp::engines::Engine::Fast),
                              in.grid, scales()[static_cast<std::size_t>(in.scale)]);
  for (const GridPoint& p : in.vertices) s += fmt::format("({},{})", p.x, p.y);
  s += "] segments=[";
  for (const GridSegment& g : in.segments) s += fmt::format("({},{})", g.a, g.b);
  s += "] holes=[";
  for (const GridPoint& h : in.holes) s += fmt::format("({},{})", h.x / 2.0, h.y / 2.0);
  s += "]";
  if (in.offset > 0) s += fmt::format(" offset=2^{}", in.offset - 1);
  if (!in.jitters.empty()) {
    s += " ulps=[";
    for (const UlpJitter& j : in.jitters) s += fmt::format("(v{}:{},{})", j.vertex, j.dx, j.dy);
    s += "]";
  }
  return s;
}

}  // namespace lepp::fuzz
