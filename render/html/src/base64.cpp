// SPDX-License-Identifier: GPL-3.0-or-later
// Base64 with Boost.Serialization's header-only iterators (lepp/html/base64.h).
#include "lepp/html/base64.h"

#include <boost/archive/iterators/base64_from_binary.hpp>
#include <boost/archive/iterators/transform_width.hpp>

namespace lepp::html {

std::string base64(std::string_view bytes) {
  using namespace boost::archive::iterators;
  using It = base64_from_binary<transform_width<std::string_view::const_iterator, 6, 8>>;
  std::string out(It(bytes.begin()), It(bytes.end()));
  out.append((3 - bytes.size() % 3) % 3, '=');
  return out;
}

}  // namespace lepp::html
