#pragma once
// HTML from the subset of Markdown the reports write (report.md): headings, paragraphs,
// pipe tables, "- " lists, fenced code blocks, images on a line of their own, **bold**,
// *italic* and `code`. Not a general Markdown parser: anything else is kept as escaped text.
#include <functional>
#include <string>

namespace swingsim {

/// What the caller puts where the Markdown has an image or a heading.
struct MarkdownHtmlHooks {
  /// HTML for `![alt](path)` on a line of its own; default: the alt text in a <p> (no <img>:
  /// the pages are self-contained).
  std::function<std::string(const std::string& alt, const std::string& path)> image;
  /// Extra HTML after the heading of `level` (1 for "#") with `text`; default none.
  std::function<std::string(int level, const std::string& text)> afterHeading;
};

/// `text` with &, <, > and " escaped for HTML text and attribute values.
std::string escapeHtml(const std::string& text);

/// The HTML body of `markdown` (no <html> or <body>): every element closed, so the result is
/// also well-formed XML.
std::string renderMarkdownHtml(const std::string& markdown, const MarkdownHtmlHooks& hooks = {});

}  // namespace swingsim
