#pragma once
// Names in files and requests checked by a plain scan: an identifier is a letter or _ and
// then letters, digits and _ (plus any of `extra`). No std::regex: libstdc++'s matcher
// recurses once per character, and a 60 kB key or message from a request overflowed the
// stack of `swingsim serve`.
#include <cctype>
#include <string_view>

namespace swingsim {

/// The length of the identifier that starts `text` (0 if none).
inline std::size_t identifierLength(std::string_view text, std::string_view extra = "") {
  const auto isStart = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; };
  if (text.empty() || !isStart(text[0])) return 0;
  std::size_t n = 1;
  while (n < text.size() && (std::isalnum(static_cast<unsigned char>(text[n])) || text[n] == '_' ||
                             extra.find(text[n]) != std::string_view::npos))
    ++n;
  return n;
}

/// Whether all of `text` is one identifier.
inline bool isIdentifier(std::string_view text, std::string_view extra = "") {
  return !text.empty() && identifierLength(text, extra) == text.size();
}

}  // namespace swingsim
