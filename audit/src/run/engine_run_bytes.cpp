// SPDX-License-Identifier: GPL-3.0-or-later
// An EngineRun as bytes and back, whole or refused (the isolated child's pipe).
#include "lepp/audit/run/engine_run_bytes.h"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <type_traits>

#include <fmt/format.h>

namespace lepp::audit {
namespace {

constexpr char kBegin[8] = {'L', 'E', 'P', 'P', 'R', 'U', 'N', '1'};
constexpr char kEnd[8] = {'E', 'N', 'D', 'R', 'U', 'N', '.', '1'};
constexpr char kCallBegin[8] = {'L', 'E', 'P', 'P', 'C', 'A', 'L', 'L'};
constexpr char kCallEnd[8] = {'E', 'N', 'D', 'C', 'A', 'L', 'L', '1'};
constexpr int kLastStatus = static_cast<int>(RunStatus::UnreadableOutput);

class Writer {
 public:
  template <class T>
  void put(T v) {
    static_assert(std::is_trivially_copyable_v<T>);
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));  // doubles keep their bits
    out_.append(b, sizeof(T));
  }
  void put_count(std::size_t n) { put(static_cast<std::uint64_t>(n)); }
  void put(const std::string& s) {
    put_count(s.size());
    out_ += s;
  }
  void put(const Point& p) {
    put(p.x);
    put(p.y);
  }
  void put(const std::vector<int>& v) {
    put_count(v.size());
    for (int i : v) put(static_cast<std::int32_t>(i));
  }
  void put_raw(const char* b, std::size_t n) { out_.append(b, n); }
  std::string take() { return std::move(out_); }

 private:
  std::string out_;
};

class Reader {
 public:
  explicit Reader(const std::string& in) : in_(in) {}
  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    need(sizeof(T), "a value");
    T v;
    std::memcpy(&v, in_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  // A count of items of `item_bytes` each: no more than the bytes left could hold.
  std::size_t get_count(std::size_t item_bytes, const char* what) {
    std::uint64_t n = get<std::uint64_t>();
    if (item_bytes > 0 && n > (in_.size() - pos_) / item_bytes)
      fail(fmt::format("{} {} claimed, the bytes left hold fewer", n, what));
    return static_cast<std::size_t>(n);
  }
  std::vector<int> get_ints(const char* what) {
    std::vector<int> v(get_count(4, what));
    for (int& i : v) i = get<std::int32_t>();
    return v;
  }
  std::string get_string(const char* what) {
    std::size_t n = get_count(1, what);
    std::string s = in_.substr(pos_, n);
    pos_ += n;
    return s;
  }
  Point get_point() {
    double x = get<double>();
    double y = get<double>();
    return {x, y};
  }
  void expect(const char (&mark)[8], const char* what) {
    need(8, what);
    if (std::memcmp(in_.data() + pos_, mark, 8) != 0) fail(std::string("no ") + what);
    pos_ += 8;
  }
  void expect_end() {
    if (pos_ != in_.size()) fail(fmt::format("{} bytes after the end mark", in_.size() - pos_));
  }
  [[noreturn]] void fail(const std::string& why) const {
    throw std::runtime_error(fmt::format("engine run bytes: {} (at byte {} of {})", why, pos_, in_.size()));
  }

 private:
  void need(std::size_t n, const char* what) const {
    if (in_.size() - pos_ < n) fail(std::string("cut short before ") + what);
  }
  const std::string& in_;
  std::size_t pos_ = 0;
};

}  // namespace

std::string encode_engine_run(const EngineRun& run) {
  Writer w;
  w.put_raw(kBegin, 8);
  w.put(static_cast<std::int32_t>(run.status));
  w.put(static_cast<std::int32_t>(run.exit_code));
  w.put(static_cast<std::int32_t>(run.signal));
  w.put(run.seconds);
  w.put(run.detail);
  w.put(run.stderr_text);
  w.put_count(run.output_files.size());
  for (const std::string& f : run.output_files) w.put(f);
  const Mesh& m = run.mesh;
  w.put_count(m.input_vertices);
  w.put_count(m.vertices.size());
  for (const Point& p : m.vertices) w.put(p);
  w.put_count(m.triangles.size());
  for (const Tri& t : m.triangles)
    for (int v : t) w.put(static_cast<std::int32_t>(v));
  w.put_count(m.constrained_edges.size());
  for (const ConstrainedEdge& e : m.constrained_edges) {
    w.put(static_cast<std::int32_t>(e.a));
    w.put(static_cast<std::int32_t>(e.b));
    w.put(static_cast<std::int32_t>(e.segment));
  }
  w.put(static_cast<std::uint8_t>(run.trace ? 1 : 0));
  if (run.trace) {
    w.put_count(run.trace->size());
    for (const Point& p : *run.trace) w.put(p);
  }
  w.put_raw(kEnd, 8);
  return w.take();
}

EngineRun decode_engine_run(const std::string& bytes) {
  Reader r(bytes);
  EngineRun run;
  r.expect(kBegin, "begin mark");
  auto status = r.get<std::int32_t>();
  if (status < 0 || status > kLastStatus) r.fail(fmt::format("status {} unknown", status));
  run.status = static_cast<RunStatus>(status);
  run.exit_code = r.get<std::int32_t>();
  run.signal = r.get<std::int32_t>();
  run.seconds = r.get<double>();
  run.detail = r.get_string("bytes of detail");
  run.stderr_text = r.get_string("bytes of stderr");
  run.output_files.resize(r.get_count(8, "output files"));
  for (std::string& f : run.output_files) f = r.get_string("bytes of a file name");
  Mesh& m = run.mesh;
  m.input_vertices = static_cast<std::size_t>(r.get<std::uint64_t>());
  m.vertices.resize(r.get_count(16, "vertices"));
  for (Point& p : m.vertices) p = r.get_point();
  m.triangles.resize(r.get_count(12, "triangles"));
  for (Tri& t : m.triangles)
    for (int& v : t) v = r.get<std::int32_t>();
  m.constrained_edges.resize(r.get_count(12, "constrained edges"));
  for (ConstrainedEdge& e : m.constrained_edges) {
    e.a = r.get<std::int32_t>();
    e.b = r.get<std::int32_t>();
    e.segment = r.get<std::int32_t>();
  }
  auto has_trace = r.get<std::uint8_t>();
  if (has_trace > 1) r.fail("trace flag neither 0 nor 1");
  if (has_trace) {
    std::vector<Point> trace(r.get_count(16, "trace points"));
    for (Point& p : trace) p = r.get_point();
    run.trace = std::move(trace);
  }
  r.expect(kEnd, "end mark");
  r.expect_end();
  return run;
}

std::string encode_engine_call(const Pslg& pslg, const EngineRequest& req) {
  Writer w;
  w.put_raw(kCallBegin, 8);
  w.put_count(pslg.vertices.size());
  for (const Point& p : pslg.vertices) w.put(p);
  w.put(pslg.vertex_markers);
  w.put_count(pslg.segments.size());
  for (const Segment& s : pslg.segments) {
    w.put(static_cast<std::int32_t>(s.a));
    w.put(static_cast<std::int32_t>(s.b));
    w.put(static_cast<std::int32_t>(s.marker));
  }
  w.put_count(pslg.holes.size());
  for (const Point& p : pslg.holes) w.put(p);
  w.put_count(pslg.regions.size());
  for (const Region& g : pslg.regions) {
    w.put(g.at);
    w.put(g.attribute);
    w.put(g.max_area);
  }
  w.put(pslg.source);
  for (const std::vector<int>* v : {&pslg.vertex_lines, &pslg.segment_lines, &pslg.hole_lines, &pslg.region_lines,
                                    &pslg.segment_origin})
    w.put(*v);
  w.put_count(pslg.crossing_vertices);
  w.put(static_cast<std::int32_t>(req.method));
  w.put(req.theta);
  w.put(req.timeout_seconds);
  w.put_count(req.memory_mb);
  w.put(req.work_dir);
  w.put_raw(kCallEnd, 8);
  return w.take();
}

void decode_engine_call(const std::string& bytes, Pslg& pslg, EngineRequest& req) {
  Reader r(bytes);
  pslg = Pslg{};
  req = EngineRequest{};
  r.expect(kCallBegin, "call mark");
  pslg.vertices.resize(r.get_count(16, "vertices"));
  for (Point& p : pslg.vertices) p = r.get_point();
  pslg.vertex_markers = r.get_ints("vertex markers");
  pslg.segments.resize(r.get_count(12, "segments"));
  for (Segment& s : pslg.segments) {
    s.a = r.get<std::int32_t>();
    s.b = r.get<std::int32_t>();
    s.marker = r.get<std::int32_t>();
  }
  pslg.holes.resize(r.get_count(16, "holes"));
  for (Point& p : pslg.holes) p = r.get_point();
  pslg.regions.resize(r.get_count(32, "regions"));
  for (Region& g : pslg.regions) {
    g.at = r.get_point();
    g.attribute = r.get<double>();
    g.max_area = r.get<double>();
  }
  pslg.source = r.get_string("bytes of the source");
  for (std::vector<int>* v : {&pslg.vertex_lines, &pslg.segment_lines, &pslg.hole_lines, &pslg.region_lines,
                              &pslg.segment_origin})
    *v = r.get_ints("line numbers");
  pslg.crossing_vertices = static_cast<std::size_t>(r.get<std::uint64_t>());
  const auto method = r.get<std::int32_t>();
  if (method != static_cast<std::int32_t>(Method::Centroid) && method != static_cast<std::int32_t>(Method::Midpoint))
    r.fail(fmt::format("method {} unknown", method));
  req.method = static_cast<Method>(method);
  req.theta = r.get<double>();
  req.timeout_seconds = r.get<double>();
  req.memory_mb = static_cast<std::size_t>(r.get<std::uint64_t>());
  req.work_dir = r.get_string("bytes of the work directory");
  r.expect(kCallEnd, "end mark");
  r.expect_end();
}

}  // namespace lepp::audit
