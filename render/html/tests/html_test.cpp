// SPDX-License-Identifier: GPL-3.0-or-later
// lepp::html: escaping, pictures with ids kept apart, the page's parts, the histogram's counts.
#include <gtest/gtest.h>

#include <string>

#include "lepp/html/base64.h"
#include "lepp/html/histogram.h"
#include "lepp/html/page.h"

namespace lepp {
namespace {

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + what.size())) ++n;
  return n;
}

TEST(HtmlEscape, MarkupFromInputFilesBecomesText) {
  EXPECT_EQ(html::escape("<script>alert('x & \"y\"')</script>"),
            "&lt;script&gt;alert(&#39;x &amp; &quot;y&quot;&#39;)&lt;/script&gt;");
  EXPECT_EQ(html::escape(std::string("a\x01" "b\tc\n", 6)), "a b\tc\n");
}

TEST(HtmlPage, TwoPicturesNeverShareAnId) {
  const std::string svg =
      "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 10 10\"><defs><clipPath "
      "id=\"window\"><rect width=\"5\" height=\"5\"/></clipPath></defs><g clip-path=\"url(#window)\"/><use href=\"#window\"/></svg>";
  html::Page page("t");
  const std::string a = page.figure(svg, "first <b>"), b = page.figure(svg, "second");
  EXPECT_EQ(a.find("<?xml"), std::string::npos);
  EXPECT_NE(a.find("id=\"p1-window\""), std::string::npos);
  EXPECT_NE(a.find("url(#p1-window)"), std::string::npos);
  EXPECT_NE(a.find("href=\"#p1-window\""), std::string::npos);
  EXPECT_NE(b.find("id=\"p2-window\""), std::string::npos);
  EXPECT_NE(b.find("url(#p2-window)"), std::string::npos);
  EXPECT_EQ(count(a + b, "\"window\""), 0u);
  EXPECT_NE(a.find("first &lt;b&gt;"), std::string::npos);
  EXPECT_EQ(page.pictures(), 2u);
}

TEST(HtmlPage, DocumentHasTheHookTheScriptAndTheBody) {
  html::Page page("a <title>");
  page.add("<p id=\"x\">body</p>");
  const std::string doc = page.str();
  EXPECT_EQ(doc.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(doc.find("<title>a &lt;title&gt;</title>"), std::string::npos);
  EXPECT_LT(doc.find("addEventListener('error'"), doc.find("<body>"));  // the hook comes before anything can fail
  EXPECT_NE(doc.find("<ol id=\"page-errors\"></ol>"), std::string::npos);
  EXPECT_LT(doc.find("<p id=\"x\">body</p>"), doc.find("panZoom"));
  EXPECT_EQ(count(doc, "http"), 0u);  // nothing fetched (no URL at all in the skeleton)
}

TEST(HtmlDetails, OpensWithoutScript) {
  EXPECT_EQ(html::details("show all <3>", "<p>x</p>"), "<details><summary>show all &lt;3&gt;</summary>\n<p>x</p></details>\n");
  EXPECT_EQ(html::details("s", "", true).rfind("<details open>", 0), 0u);
}

TEST(HtmlBase64, Rfc4648Vectors) {
  EXPECT_EQ(html::base64(""), "");
  EXPECT_EQ(html::base64("f"), "Zg==");
  EXPECT_EQ(html::base64("fo"), "Zm8=");
  EXPECT_EQ(html::base64("foo"), "Zm9v");
  EXPECT_EQ(html::base64("foob"), "Zm9vYg==");
  EXPECT_EQ(html::base64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(html::base64("foobar"), "Zm9vYmFy");
}

TEST(HtmlHistogram, OneBarPerNonEmptyBinRedBelowTheMark) {
  html::HistogramOptions o;
  o.lo = 0, o.hi = 60, o.bins = 6, o.mark = 30, o.mark_label = "theta <30>";
  // bins of 10 degrees: 5 -> bin 0, 12 and 15 -> bin 1, 45 -> bin 4, 70 -> clamped into bin 5; NaN left out.
  const std::string svg = html::histogram_svg({5, 12, 15, 45, 70, 0.0 / 0.0}, o);
  EXPECT_EQ(count(svg, "<title>"), 4u);
  EXPECT_EQ(count(svg, "fill=\"#c0392b\"><title>"), 2u);  // bins 0 and 1, below 30
  EXPECT_NE(svg.find("<title>2</title>"), std::string::npos);
  EXPECT_NE(svg.find("theta &lt;30&gt;"), std::string::npos);
}

}  // namespace
}  // namespace lepp
