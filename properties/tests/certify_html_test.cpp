// SPDX-License-Identifier: GPL-3.0-or-later
// lepp::certify::html_report: the page says what the report says (verdict, one row
// and one section per kind with its count, every listed violation once, the rest
// behind "show all"), escapes what comes from files, and draws a large mesh as
// its outline. Triangle's mesh of A at 30 degrees, certified at 30 (it holds) and
// at 33 (triangles below), and with a vertex moved (not locally Delaunay too).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>

#include "lepp/certify.h"
#include "lepp/certify_html.h"
#include "lepp/io.h"
#include "lepp/validate.h"

namespace lepp {
namespace {

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + what.size())) ++n;
  return n;
}

struct Case {
  Pslg input;
  Mesh mesh;
};

Case sample() {
  std::vector<std::string> warnings;
  return {validate(read_poly(LEPP_SOURCE_DIR "/corpus/paper/A.poly"), warnings), read_mesh(LEPP_SOURCE_DIR "/paper/testdata/A-triangle-q30")};
}

certify::Report certified_at(const Case& c, double theta) {
  certify::Options o;
  o.min_angle_deg = theta;
  return certify::certify(c.input, c.mesh, o);
}

TEST(CertifyHtml, CertifiedMeshHasTheVerdictTheStatisticsAndTwoPictures) {
  const Case c = sample();
  const certify::Report r = certified_at(c, 30);
  ASSERT_TRUE(r.certified());
  const std::string page = certify::html_report(c.mesh, r);
  EXPECT_NE(page.find("data-certified=\"true\""), std::string::npos);
  EXPECT_EQ(page.find("id=\"counts\""), std::string::npos);  // no violations, no table of them
  EXPECT_NE(page.find("id=\"statistics\""), std::string::npos);
  EXPECT_NE(page.find("<td class=\"n\">" + std::to_string(c.mesh.triangles.size()) + "</td>"), std::string::npos);
  EXPECT_EQ(count(page, "class=\"pz picture\""), 2u);  // the histogram and the overview
  EXPECT_EQ(count(page, "class=\"violation\""), 0u);
}

TEST(CertifyHtml, EveryKindHasItsRowAndSectionAndEveryListedViolationAppearsOnce) {
  Case c = sample();
  // A Steiner vertex moved a little: its triangles stop being locally Delaunay, and at 33 degrees many are below theta.
  c.mesh.vertices[c.mesh.input_vertices + 3].x += 0.004;
  const certify::Report r = certified_at(c, 33);
  ASSERT_FALSE(r.certified());
  std::map<certify::Reason, std::size_t> listed;
  for (const certify::Violation& v : r.violations) ++listed[v.reason];
  ASSERT_GE(listed.size(), 2u) << certify::format_report(r);
  ASSERT_GT(listed[certify::Reason::AngleBelowTheta], 5u);  // more than shown at once: the rest behind "show all"
  certify::HtmlOptions o;
  o.shown_per_reason = 5;
  const std::string page = certify::html_report(c.mesh, r, o);
  EXPECT_NE(page.find("data-certified=\"false\""), std::string::npos);
  std::size_t kinds = 0, drawn = 0;
  for (const auto& [reason, n] : listed) {
    const std::string name = certify::to_string(reason);
    ++kinds;
    EXPECT_NE(page.find("<tr data-reason=\"" + name + "\" data-count=\"" + std::to_string(r.count(reason)) + "\">"), std::string::npos) << name;
    EXPECT_NE(page.find("data-reason=\"" + name + "\" data-count=\"" + std::to_string(r.count(reason)) + "\" data-listed=\"" +
                        std::to_string(n) + "\""),
              std::string::npos)
        << name;
    EXPECT_EQ(count(page, "<div class=\"violation\" data-reason=\"" + name + "\">"), n) << name;
    std::string sentence = certify::explanation(reason);
    for (std::size_t at = sentence.find('\''); at != std::string::npos; at = sentence.find('\'', at)) sentence.replace(at, 1, "&#39;");
    EXPECT_NE(page.find("<p>" + sentence + "</p>"), std::string::npos) << name;
  }
  EXPECT_EQ(count(page, "<tr data-reason="), kinds);
  EXPECT_EQ(count(page, "<details><summary>show all"), static_cast<std::size_t>(std::count_if(
                                                          listed.begin(), listed.end(), [](const auto& kv) { return kv.second > 5; })));
  // Each violation that names a triangle, an edge or a point has its picture, besides the histogram and the overview.
  for (const certify::Violation& v : r.violations) drawn += !v.triangles.empty() || !v.edges.empty() || !v.points.empty();
  EXPECT_EQ(count(page, "class=\"pz picture\""), 2 + drawn);
  // Its exact coordinates, as written in the mesh file (17 digits).
  const Point& p = c.mesh.vertices[c.mesh.input_vertices + 3];
  EXPECT_NE(page.find(fmt::format("({:.17g}, {:.17g})", p.x, p.y)), std::string::npos);
}

TEST(CertifyHtml, StringsFromFilesAreEscaped) {
  const Case c = sample();
  certify::Report r = certified_at(c, 33);
  ASSERT_FALSE(r.violations.empty());
  r.violations.front().message = "<script>alert('message')</script>";
  certify::HtmlOptions o;
  o.title = "<script>alert('title')</script>.poly";
  o.command = "lepp certify <img src=x onerror=alert(1)>";
  const std::string page = certify::html_report(c.mesh, r, o);
  EXPECT_EQ(page.find("<script>alert"), std::string::npos);
  EXPECT_EQ(page.find("<img src=x"), std::string::npos);
  EXPECT_NE(page.find("&lt;script&gt;alert(&#39;title&#39;)&lt;/script&gt;.poly"), std::string::npos);
  EXPECT_NE(page.find("&lt;script&gt;alert(&#39;message&#39;)&lt;/script&gt;"), std::string::npos);
}

TEST(CertifyHtml, LargeMeshOverviewIsTheOutlineOnly) {
  const Case c = sample();
  const certify::Report r = certified_at(c, 33);
  certify::HtmlOptions small, large;
  large.outline_above = 10;  // A's mesh counts as large
  const std::string whole = certify::html_report(c.mesh, r, small), outline = certify::html_report(c.mesh, r, large);
  // The overview is the first picture after "The mesh": triangles are filled paths in viridis bins there.
  auto overview = [](const std::string& page) {
    const std::size_t at = page.find("<figure class=\"overview\">");
    return page.substr(at, page.find("</figure>", at) - at);
  };
  EXPECT_NE(overview(whole).find("fill=\"#fde725\" d="), std::string::npos);
  EXPECT_EQ(overview(outline).find("fill=\"#fde725\" d="), std::string::npos);
  EXPECT_NE(overview(outline).find("stroke=\"#555\""), std::string::npos);  // the boundary
  EXPECT_NE(overview(outline).find("stroke=\"red\""), std::string::npos);   // the violations marked
  // One stroke per boundary edge (an edge of one triangle), counted here from the triangles.
  std::map<std::pair<int, int>, int> uses;
  for (const Tri& t : c.mesh.triangles)
    for (std::size_t i = 0; i < 3; ++i) ++uses[std::minmax(t[i], t[(i + 1) % 3])];
  std::size_t boundary = 0;
  for (const auto& [e, n] : uses) boundary += n == 1;
  const std::string o = overview(outline);
  const std::size_t d = o.find(" d=\"", o.find("stroke=\"#555\""));
  EXPECT_EQ(count(o.substr(d, o.find('"', d + 4) - d), "M"), boundary);
}

TEST(CertifyHtml, UndrawableMeshSaysWhyInsteadOfAPicture) {
  Case c = sample();
  c.mesh.triangles[0][1] = static_cast<int>(c.mesh.vertices.size()) + 7;  // a vertex id out of range
  const certify::Report r = certified_at(c, 0);
  ASSERT_TRUE(r.has(certify::Reason::BadTriangle));
  const std::string page = certify::html_report(c.mesh, r);
  EXPECT_NE(page.find("no picture: render: vertex id"), std::string::npos);
  EXPECT_NE(page.find("data-reason=\"bad-triangle\""), std::string::npos);
}

}  // namespace
}  // namespace lepp
