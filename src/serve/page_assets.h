#pragma once
// The files of swingsim serve's page (src/serve/page/), embedded at build time
// (cmake/embed_page.cmake): an installed swingsim serves them without the source tree.
#include <optional>
#include <string>
#include <string_view>

namespace swingsim {

/// The bytes of page file `name` ("index.html", "page.js", "page.css"); nullopt for any
/// other name. A name is looked up in the embedded list, never opened as a path.
std::optional<std::string_view> findPageAsset(const std::string& name);

}  // namespace swingsim
