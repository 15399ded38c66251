// SPDX-License-Identifier: GPL-3.0-or-later
// The page skeleton and its pictures (lepp/html/page.h).
#include "lepp/html/page.h"

#include <fstream>
#include <set>
#include <sstream>

#include "lepp/html/base64.h"
#include "page_assets.h"

namespace lepp::html {
namespace {

// The document without what only a standalone file needs (<?xml ...?>, <!DOCTYPE ...>).
std::string_view drop_prolog(std::string_view svg) {
  const std::size_t at = svg.find("<svg");
  return at == std::string_view::npos ? svg : svg.substr(at);
}

// Every id="X" of the document renamed PREFIX-X, and the references to it
// (url(#X), href="#X", xlink:href="#X"): two pictures in one page never share an id.
std::string prefix_ids(std::string_view svg, const std::string& prefix) {
  std::set<std::string> ids;
  for (std::size_t at = svg.find(" id=\""); at != std::string_view::npos; at = svg.find(" id=\"", at + 5)) {
    const std::size_t end = svg.find('"', at + 5);
    if (end == std::string_view::npos) break;
    ids.emplace(svg.substr(at + 5, end - at - 5));
  }
  std::string out(svg);
  if (ids.empty()) return out;
  auto replace_all = [&out](const std::string& from, const std::string& to) {
    for (std::size_t at = out.find(from); at != std::string::npos; at = out.find(from, at + to.size()))
      out.replace(at, from.size(), to);
  };
  for (const std::string& id : ids) {
    replace_all(" id=\"" + id + "\"", " id=\"" + prefix + id + "\"");
    replace_all("url(#" + id + ")", "url(#" + prefix + id + ")");
    replace_all("href=\"#" + id + "\"", "href=\"#" + prefix + id + "\"");
  }
  return out;
}

}  // namespace

Page& Page::add(std::string_view html) {
  body_ += html;
  return *this;
}

std::string Page::figure(const std::string& svg, std::string_view caption, std::string_view css_class) {
  const std::string prefix = "p" + std::to_string(++pictures_) + "-";
  std::string out = "<figure";
  if (!css_class.empty()) out += " class=\"" + escape(css_class) + "\"";
  out += "><div class=\"pz picture\" title=\"drag to pan, wheel to zoom, double-click to reset\">";
  out += prefix_ids(drop_prolog(svg), prefix);
  out += "</div>";
  if (!caption.empty()) out += "<figcaption>" + escape(caption) + "</figcaption>";
  out += "</figure>\n";
  return out;
}

std::string Page::png_figure(std::string_view png, std::string_view caption) {
  ++pictures_;
  std::string out = "<figure><div class=\"picture\"><img alt=\"" + escape(caption) + "\" src=\"data:image/png;base64,";
  out += base64(png);
  out += "\"></div>";
  if (!caption.empty()) out += "<figcaption>" + escape(caption) + "</figcaption>";
  out += "</figure>\n";
  return out;
}

std::string Page::str() const {
  std::string out = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  out += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  out += "<title>" + escape(title_) + "</title>\n";
  out += std::string("<script>") + detail::kErrorHook + "</script>\n";
  out += std::string("<style>") + detail::kStyle + "</style>\n";
  out += "</head>\n<body>\n<ol id=\"page-errors\"></ol>\n";
  out += body_;
  out += std::string("<script>") + detail::kScript + "</script>\n</body>\n</html>\n";
  return out;
}

std::string details(std::string_view summary, std::string_view body, bool open) {
  std::string out = open ? "<details open>" : "<details>";
  out += "<summary>" + escape(summary) + "</summary>\n";
  out += body;
  out += "</details>\n";
  return out;
}

std::optional<std::string> file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace lepp::html
