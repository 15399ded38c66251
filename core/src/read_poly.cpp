// SPDX-License-Identifier: GPL-3.0-or-later
// Triangle's .poly and .node readers: syntax only (geometry is validate()'s job).
#include <algorithm>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "lepp/input.h"
#include "lepp/io.h"
#include "line_reader.h"
#include "node_reader.h"

namespace lepp {

InputError::InputError(std::string file, int line, const std::string& what)
    : std::runtime_error(line > 0 ? fmt::format("{}:{}: {}", file, line, what) : fmt::format("{}: {}", file, what)),
      file_(std::move(file)),
      line_(line) {}

namespace {

using detail::LineReader;
using Tokens = std::vector<std::string_view>;

// What Triangle tolerates and lepp follows, noted per file for one warning
// each: trailing fields beyond what the header announces (Triangle never reads
// them) and optional fields (attributes, markers, a region's area) left out
// (Triangle reads them as 0).
struct Leniency {
  std::string path;
  int first_extra_line = 0, extra_lines = 0;
  int first_short_line = 0, short_lines = 0;
  void report(std::vector<std::string>& warnings) const {
    if (extra_lines)
      warnings.push_back(fmt::format("{}:{}: extra fields after what the header announces are ignored, as Triangle "
                                     "does ({} line{})",
                                     path, first_extra_line, extra_lines, extra_lines == 1 ? "" : "s"));
    if (short_lines)
      warnings.push_back(fmt::format("{}:{}: attributes or markers the header announces are missing and read as 0, "
                                     "as Triangle does ({} line{})",
                                     path, first_short_line, short_lines, short_lines == 1 ? "" : "s"));
  }
};

// The lines of one section (vertices, segments, holes, regions): `need` fields
// at least, `want` announced by the header. Extra fields are ignored when they
// form a column (every line of the section has them, as when a writer puts a
// marker on every segment line); a section where only some lines carry extras
// is taken for a typo and rejected at the first such line.
class Section {
 public:
  // Lines with more than `max` (default `want`) fields have extra fields.
  Section(LineReader& in, Leniency& lenient, std::size_t need, std::size_t want, const char* what, std::size_t max = 0)
      : in_(in), lenient_(lenient), need_(need), want_(want), max_(std::max(max, want)), what_(what) {}
  // A line LineReader::plain read: exactly the announced fields, nothing to note.
  void plain_line() { ++lines_; }
  // Checks the field count of the line just read.
  void line(const Tokens& t) {
    ++lines_;
    if (t.size() < need_) in_.fail(fmt::format("{}: expected {} fields, found {}", what_, need_, t.size()));
    if (t.size() < want_ && !lenient_.first_short_line) lenient_.first_short_line = in_.line();
    if (t.size() < want_) ++lenient_.short_lines;
    if (t.size() > max_) {
      if (!first_extra_) first_extra_ = in_.line(), extra_fields_ = t.size();
      ++extras_;
    }
  }
  // After the last line: a column of extras is fine, a few stray ones are not.
  void done() {
    if (extras_ == 0) return;
    if (extras_ != lines_) {
      in_.fail_at(first_extra_, fmt::format("{}: expected at most {} fields, found {} (extra fields, on {} of the section's {} lines; "
                           "an extra column on every line would be ignored)",
                           what_, max_, extra_fields_, extras_, lines_));
    }
    if (!lenient_.first_extra_line) lenient_.first_extra_line = first_extra_;
    lenient_.extra_lines += static_cast<int>(extras_);
  }

 private:
  LineReader& in_;
  Leniency& lenient_;
  std::size_t need_, want_, max_;
  const char* what_;
  std::size_t lines_ = 0, extras_ = 0, extra_fields_ = 0;
  int first_extra_ = 0;
};

// A header count: non-negative and no larger than the lines left to hold it,
// so a lying header cannot make us allocate or loop.
std::size_t count(LineReader& in, std::string_view token, const char* what, std::size_t lines_per_item = 1) {
  std::int64_t n = in.integer(token, what);
  if (n < 0) in.fail(fmt::format("{} is negative ({})", what, n));
  if (n > 0 && static_cast<std::size_t>(n) > in.lines_left() / lines_per_item)
    in.fail(LineReader::too_many(what, n, in.lines_left()));
  return static_cast<std::size_t>(n);
}

// A header line: `need` fields at least; further fields Triangle ignores.
void header(LineReader& in, Leniency& lenient, const Tokens& t, std::size_t need, std::size_t want, const char* what) {
  Section h(in, lenient, need, want, what);
  h.line(t);
  h.done();
}

// Reads the vertex section: header already in `header`. Sets first index (0 or 1).
// vertices_only: no vertex_lines, no vertex_markers (read_node_numbered).
void read_vertices(LineReader& in, Leniency& lenient, const Tokens& head, Pslg& pslg, int& first, bool vertices_only = false) {
  header(in, lenient, head, 1, 4, "vertex header (count, dimension, attributes, markers)");
  // count()'s check, made only if an error comes before the n lines are read (LineReader::count_later).
  const std::int64_t count_read = in.integer(head[0], "vertex count");
  if (count_read < 0) in.fail(fmt::format("vertex count is negative ({})", count_read));
  const std::size_t n = static_cast<std::size_t>(count_read);
  in.count_later(n, "vertex count");
  if (head.size() >= 2 && in.integer(head[1], "dimension") != 2) in.fail("dimension must be 2");
  std::int64_t attributes = head.size() >= 3 ? in.integer(head[2], "attribute count") : 0;
  if (attributes < 0 || attributes > 1000) in.fail(fmt::format("attribute count {} is out of range", attributes));
  std::int64_t markers = head.size() >= 4 ? in.integer(head[3], "boundary marker count") : 0;
  if (markers != 0 && markers != 1) in.fail("boundary marker count must be 0 or 1");
  const std::size_t fields = 3 + static_cast<std::size_t>(attributes) + static_cast<std::size_t>(markers);
  const std::size_t room = std::min(n, in.bytes_left() / 4 + 1);  // a line is 6 bytes at least: n unless the count is wrong
  const bool lines = !vertices_only, keep_markers = markers && !vertices_only;
  pslg.vertices.reserve(room);
  if (lines) pslg.vertex_lines.reserve(room);
  if (keep_markers) pslg.vertex_markers.reserve(room);
  Section section(in, lenient, 3, fields, "vertex line (number, x, y, attributes, marker)");
  // The plain line's kinds: the number, x, y, the attributes, the marker.
  const std::string kinds = "irr" + std::string(static_cast<std::size_t>(attributes), 'r') + (markers ? "i" : "");
  std::vector<double> reals(2 + static_cast<std::size_t>(attributes));
  std::int64_t ints[2];
  Tokens t;
  for (std::size_t i = 0; i < n; ++i) {
    // The vertex's number: the first 0 or 1, each next one more.
    auto numbered = [&](std::int64_t number) {
      if (i == 0) {
        if (number != 0 && number != 1) in.fail(fmt::format("first vertex is numbered {}; must be 0 or 1", number));
        first = static_cast<int>(number);
      } else if (number != first + static_cast<std::int64_t>(i)) {
        in.fail(fmt::format("vertex number {} out of order (expected {})", number, first + static_cast<std::int64_t>(i)));
      }
    };
    if (in.plain(kinds.c_str(), ints, reals.data())) {  // the common line, read in one pass
      section.plain_line();
      numbered(ints[0]);
      pslg.vertices.push_back({reals[0], reals[1]});
      if (keep_markers) pslg.vertex_markers.push_back(static_cast<int>(ints[1]));
    } else {
      in.expect_item(t, "vertex", i + 1, n);
      section.line(t);
      numbered(in.integer(t[0], "vertex number"));  // checked before the coordinates are read
      pslg.vertices.push_back({in.real(t[1], "x coordinate"), in.real(t[2], "y coordinate")});
      const std::size_t present = std::min(t.size(), fields);
      for (std::size_t a = 3; a < std::min(present, 3 + static_cast<std::size_t>(attributes)); ++a) in.real(t[a], "attribute");
      if (markers) {  // read (and checked) either way
        const int marker = present == fields ? static_cast<int>(in.integer(t[fields - 1], "boundary marker")) : 0;
        if (keep_markers) pslg.vertex_markers.push_back(marker);
      }
    }
    if (lines) pslg.vertex_lines.push_back(in.line());
  }
  in.count_kept();
  section.done();
}

std::string node_path_for(const std::string& poly_path) {
  std::string base = poly_path;
  if (base.size() > 5 && base.compare(base.size() - 5, 5, ".poly") == 0) base.resize(base.size() - 5);
  return base + ".node";
}

bool ends_with(const std::string& s, const char* tail) {
  const std::size_t n = std::char_traits<char>::length(tail);
  return s.size() >= n && s.compare(s.size() - n, n, tail) == 0;
}

// True unless the path is known not to exist: a path we cannot stat (no
// permission on a parent, ...) counts as there, so reading it gives the real error.
bool may_exist(const std::string& path) {
  std::error_code ec;
  return std::filesystem::exists(path, ec) || ec;
}

bool is_directory(const std::string& path) {
  std::error_code ec;
  return std::filesystem::is_directory(path, ec);
}

}  // namespace

Pslg detail::read_node_numbered(const std::string& path, std::vector<std::string>& warnings, int& first, bool vertices_only) {
  LineReader in(path);
  Leniency lenient{path};
  Pslg pslg;
  pslg.source = path;
  Tokens t;
  in.expect(t, "vertex header");
  first = 1;
  read_vertices(in, lenient, t, pslg, first, vertices_only);
  if (in.next(t)) in.fail("unexpected content after the last vertex");
  lenient.report(warnings);
  return pslg;
}

Pslg read_node(const std::string& path, std::vector<std::string>& warnings) {
  int first = 1;
  return detail::read_node_numbered(path, warnings, first);
}

Pslg read_node(const std::string& path) {
  std::vector<std::string> ignored;
  return read_node(path, ignored);
}

Pslg read_poly(const std::string& path, std::vector<std::string>& warnings) {
  LineReader in(path);
  Leniency lenient{path};
  Pslg pslg;
  pslg.source = path;
  Tokens t;
  int first = 1;
  in.expect(t, "vertex header (count, dimension, attributes, markers)");
  read_vertices(in, lenient, t, pslg, first);
  if (pslg.vertices.empty()) {
    // Triangle: a .poly with no vertices takes them from the .node beside it.
    std::string node = node_path_for(path);
    if (!std::ifstream(node)) in.fail(fmt::format("the .poly lists no vertices and {} cannot be opened", node));
    Pslg points = read_node(node, warnings);
    // Written back, a .poly with no vertices would again point at a .node: refuse the
    // empty set here, naming both files, rather than accept what cannot be written.
    if (points.vertices.empty()) in.fail(fmt::format("the .poly lists no vertices and neither does {}", node));
    pslg.vertices = std::move(points.vertices);
    pslg.vertex_markers = std::move(points.vertex_markers);
    pslg.vertex_lines = std::move(points.vertex_lines);
    if (!pslg.vertices.empty()) {  // the .node's numbering (0 or 1) is the segments' too
      LineReader probe(node);
      Tokens h;
      probe.expect(h, "vertex header");
      probe.expect(h, "vertex 1");
      first = static_cast<int>(probe.integer(h[0], "vertex number"));
    }
  }
  const std::int64_t nv = static_cast<std::int64_t>(pslg.vertices.size());

  in.expect(t, "segment header (count, markers)");
  header(in, lenient, t, 1, 2, "segment header (count, markers)");
  std::size_t ns = count(in, t[0], "segment count");
  std::int64_t markers = t.size() >= 2 ? in.integer(t[1], "boundary marker count") : 0;
  if (markers != 0 && markers != 1) in.fail("boundary marker count must be 0 or 1");
  pslg.segments.reserve(ns);
  pslg.segment_lines.reserve(ns);
  const std::size_t fields = 3 + static_cast<std::size_t>(markers);
  Section segments(in, lenient, 3, fields, "segment line (number, endpoint, endpoint, marker)");
  for (std::size_t i = 0; i < ns; ++i) {
    in.expect_item(t, "segment", i + 1, ns);
    segments.line(t);
    std::int64_t number = in.integer(t[0], "segment number");
    if (number != first + static_cast<std::int64_t>(i))
      in.fail(fmt::format("segment number {} out of order (expected {})", number, first + static_cast<std::int64_t>(i)));
    Segment s;
    std::int64_t ends[2];
    for (int k = 0; k < 2; ++k) {
      ends[k] = in.integer(t[1 + static_cast<std::size_t>(k)], "segment endpoint");
      if (ends[k] < first || ends[k] >= first + nv)
        in.fail(fmt::format("segment endpoint {} out of range (vertices are numbered {} to {})", ends[k], first,
                            first + nv - 1));
    }
    // Both endpoints one vertex: lepp::validate drops it with a warning (Triangle does).
    s.a = static_cast<int>(ends[0] - first);
    s.b = static_cast<int>(ends[1] - first);
    if (markers && t.size() >= fields) s.marker = static_cast<int>(in.integer(t[3], "boundary marker"));
    pslg.segments.push_back(s);
    pslg.segment_lines.push_back(in.line());
  }
  segments.done();

  // Triangle allows the hole section to be missing entirely.
  if (!in.next(t)) {
    lenient.report(warnings);
    return pslg;
  }
  header(in, lenient, t, 1, 1, "hole header (count)");
  std::size_t nh = count(in, t[0], "hole count");
  Section holes(in, lenient, 3, 3, "hole line (number, x, y)");
  for (std::size_t i = 0; i < nh; ++i) {
    in.expect_item(t, "hole", i + 1, nh);
    holes.line(t);
    in.integer(t[0], "hole number");
    pslg.holes.push_back({in.real(t[1], "hole x"), in.real(t[2], "hole y")});
    pslg.hole_lines.push_back(in.line());
  }
  holes.done();

  // Optional regional attributes and area constraints (Triangle's -A and -a):
  // `number x y attribute [max area]`; with one value, Triangle takes it as
  // both the attribute and the area bound.
  if (in.next(t)) {
    header(in, lenient, t, 1, 1, "region header (count)");
    std::size_t nr = count(in, t[0], "region count");
    Section regions(in, lenient, 4, 4, "region line (number, x, y, attribute, max area)", 5);
    for (std::size_t i = 0; i < nr; ++i) {
      in.expect_item(t, "region", i + 1, nr);
      regions.line(t);
      in.integer(t[0], "region number");
      Region r;
      r.at = {in.real(t[1], "region x"), in.real(t[2], "region y")};
      r.attribute = in.real(t[3], "regional attribute");
      r.max_area = t.size() >= 5 ? in.real(t[4], "region area bound") : r.attribute;
      pslg.regions.push_back(r);
      pslg.region_lines.push_back(in.line());
    }
    regions.done();
    if (in.next(t)) in.fail("unexpected content after the last section");
  }
  lenient.report(warnings);
  return pslg;
}

Pslg read_poly(const std::string& path) {
  std::vector<std::string> ignored;
  return read_poly(path, ignored);
}

Pslg read_input(const std::string& path, std::vector<std::string>& warnings) {
  if (ends_with(path, ".node")) return read_node(path, warnings);
  const bool directory = is_directory(path);
  if (ends_with(path, ".poly") || (may_exist(path) && !directory)) return read_poly(path, warnings);
  // A bare prefix, as Triangle takes one (`triangle -p X` reads X.poly,
  // `triangle X` reads X.node): X.poly if it is there, else X.node.
  const std::string poly = path + ".poly", node = path + ".node";
  if (may_exist(poly)) return read_poly(poly, warnings);
  if (may_exist(node)) return read_node(node, warnings);
  throw InputError(path, 0, fmt::format("{}; read as a prefix, neither {} nor {} exists",
                                        directory ? "is a directory" : "no such file", poly, node));
}

}  // namespace lepp
