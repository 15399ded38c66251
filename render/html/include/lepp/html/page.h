// SPDX-License-Identifier: GPL-3.0-or-later
// One self-contained HTML page (no network, no other file): the report of
// `lepp certify --html`, `lepp audit --html`, `lepp paper` and Python's
// _repr_html_. The page carries its style, a small pan/zoom script for its
// pictures and a hook that writes script errors into the page (#page-errors),
// which the browser check (scripts/check_html_page.py) reads. Opened with
// "#check" in its address, the page opens every <details> and writes each
// picture's place and size into its data-x/-y/-w/-h attributes.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace lepp::html {

// Text made safe for HTML element content and attribute values: & < > " ' as
// entities, control characters other than tab and newline as spaces.
std::string escape(std::string_view text);

// A page being written: its body and the pictures it holds.
class Page {
 public:
  explicit Page(std::string title) : title_(std::move(title)) {}

  // Raw HTML appended to the body (the caller escapes what it puts in it).
  Page& add(std::string_view html);
  // A picture from an SVG document (render_svg's or any): the XML prolog dropped, its
  // ids made unique in the page (two pictures' clip paths must not meet), in a frame
  // that pans (drag) and zooms (wheel; double-click resets). `caption` is text.
  std::string figure(const std::string& svg, std::string_view caption, std::string_view css_class = "");
  // A raster picture (PNG bytes) inlined as a data: URI, with its caption.
  std::string png_figure(std::string_view png, std::string_view caption);

  std::size_t pictures() const { return pictures_; }
  // The whole document: <!DOCTYPE html>, head with style and scripts, the body.
  std::string str() const;

 private:
  std::string title_, body_;
  std::size_t pictures_ = 0;
};

// The bytes of a file a page inlines (an SVG, a PNG), or nothing when it cannot be read.
std::optional<std::string> file_bytes(const std::string& path);

// <details> with a <summary> (text, escaped) around raw HTML: opens without any script.
std::string details(std::string_view summary, std::string_view body, bool open = false);

}  // namespace lepp::html
