#include "report/markdown_html.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <sstream>
#include <vector>

#include "report/svg_plot.h"

namespace swingsim {

std::string escapeHtml(const std::string& text) { return svgEscape(text); }  // the same characters as in SVG

namespace {

bool startsWith(const std::string& s, const std::string& prefix) { return s.compare(0, prefix.size(), prefix) == 0; }

// Escaped text with **bold**, *italic* and `code` spans; an unpaired marker stays as text.
std::string renderInline(const std::string& text) {
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    if (text[i] == '`') {
      const std::size_t end = text.find('`', i + 1);
      if (end != std::string::npos) {
        out += "<code>" + escapeHtml(text.substr(i + 1, end - i - 1)) + "</code>";
        i = end + 1;
        continue;
      }
    } else if (text.compare(i, 2, "**") == 0) {
      const std::size_t end = text.find("**", i + 2);
      if (end != std::string::npos) {
        out += "<strong>" + renderInline(text.substr(i + 2, end - i - 2)) + "</strong>";
        i = end + 2;
        continue;
      }
    } else if (text[i] == '*' && i + 1 < text.size() && text[i + 1] != ' ') {
      const std::size_t end = text.find('*', i + 1);
      if (end != std::string::npos && text[end - 1] != ' ') {
        out += "<em>" + renderInline(text.substr(i + 1, end - i - 1)) + "</em>";
        i = end + 1;
        continue;
      }
    }
    out += escapeHtml(std::string(1, text[i]));
    ++i;
  }
  return out;
}

// The cells of a pipe-table row "| a | b |".
std::vector<std::string> splitRow(const std::string& line) {
  std::vector<std::string> cells;
  std::string inner = line.substr(1);
  if (!inner.empty() && inner.back() == '|') inner.pop_back();
  std::size_t start = 0;
  while (true) {
    const std::size_t bar = inner.find('|', start);
    std::string cell = inner.substr(start, bar == std::string::npos ? std::string::npos : bar - start);
    const auto first = cell.find_first_not_of(' '), last = cell.find_last_not_of(' ');
    cells.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
    if (bar == std::string::npos) break;
    start = bar + 1;
  }
  return cells;
}

bool isSeparatorRow(const std::string& line) { return line.find_first_not_of("|-: ") == std::string::npos; }

// Renders line by line; each block kind closes itself when a line of another kind comes.
class MarkdownRenderer {
 public:
  explicit MarkdownRenderer(const MarkdownHtmlHooks& hooks) : hooks_(hooks) {}

  void addLine(const std::string& line) {
    if (inCode_) {
      if (startsWith(line, "```")) {
        html_ += "</code></pre>\n";
        inCode_ = false;
      } else {
        html_ += escapeHtml(line) + "\n";
      }
      return;
    }
    if (startsWith(line, "```")) {
      closeBlocks();
      html_ += "<pre><code>";
      inCode_ = true;
    } else if (line.empty()) {
      closeBlocks();
    } else if (line[0] == '#') {
      addHeading(line);
    } else if (line[0] == '|') {
      addTableRow(line);
    } else if (startsWith(line, "- ")) {
      if (block_ != Block::kList) {
        closeBlocks();
        html_ += "<ul>\n";
        block_ = Block::kList;
      }
      html_ += "<li>" + renderInline(line.substr(2)) + "</li>\n";
    } else if (startsWith(line, "![") && line.back() == ')' && line.find("](") != std::string::npos) {
      closeBlocks();
      const std::size_t mid = line.find("](");
      const std::string alt = line.substr(2, mid - 2), path = line.substr(mid + 2, line.size() - mid - 3);
      html_ += hooks_.image ? hooks_.image(alt, path) : "<p>" + escapeHtml(alt) + "</p>\n";
    } else {
      if (block_ != Block::kParagraph) {
        closeBlocks();
        html_ += "<p>";
        block_ = Block::kParagraph;
      } else {
        html_ += "\n";
      }
      html_ += renderInline(line);
    }
  }

  std::string finish() {
    if (inCode_) html_ += "</code></pre>\n";
    inCode_ = false;
    closeBlocks();
    return html_;
  }

 private:
  enum class Block { kNone, kParagraph, kList, kTable };

  void closeBlocks() {
    if (block_ == Block::kParagraph) html_ += "</p>\n";
    if (block_ == Block::kList) html_ += "</ul>\n";
    if (block_ == Block::kTable) html_ += "</tbody></table>\n";
    block_ = Block::kNone;
  }

  void addHeading(const std::string& line) {
    closeBlocks();
    const int level = static_cast<int>(std::min<std::size_t>(line.find_first_not_of('#'), 6));
    const std::string text = line.substr(std::min(line.size(), static_cast<std::size_t>(level) + 1));
    const std::string tag = "h" + std::to_string(level);
    html_ += "<" + tag + " id=\"" + makeAnchor(text) + "\">" + renderInline(text) + "</" + tag + ">\n";
    if (hooks_.afterHeading) html_ += hooks_.afterHeading(level, text);
  }

  // The heading's id, for links to it (REPORT.html#p1): lower-case letters and digits, "-"
  // between words, and "-2", "-3" on a repeat.
  std::string makeAnchor(const std::string& text) {
    std::string id;
    for (char c : text) {
      if (std::isalnum(static_cast<unsigned char>(c)))
        id += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      else if (!id.empty() && id.back() != '-')
        id += '-';
    }
    while (!id.empty() && id.back() == '-') id.pop_back();
    if (id.empty()) id = "section";
    const int seen = ++anchors_[id];
    return seen == 1 ? id : id + "-" + std::to_string(seen);
  }

  // The first row of a table is its header; the separator row "|---|" is dropped.
  void addTableRow(const std::string& line) {
    if (block_ != Block::kTable) {
      closeBlocks();
      html_ += "<table>\n<thead><tr>";
      for (const auto& c : splitRow(line)) html_ += "<th>" + renderInline(c) + "</th>";
      html_ += "</tr></thead>\n<tbody>\n";
      block_ = Block::kTable;
      return;
    }
    if (isSeparatorRow(line)) return;
    html_ += "<tr>";
    for (const auto& c : splitRow(line)) html_ += "<td>" + renderInline(c) + "</td>";
    html_ += "</tr>\n";
  }

  const MarkdownHtmlHooks& hooks_;
  std::string html_;
  Block block_ = Block::kNone;
  std::map<std::string, int> anchors_;  // heading ids so far, with their counts
  bool inCode_ = false;
};

}  // namespace

std::string renderMarkdownHtml(const std::string& markdown, const MarkdownHtmlHooks& hooks) {
  MarkdownRenderer renderer(hooks);
  std::istringstream in(markdown);
  std::string line;
  while (std::getline(in, line)) renderer.addLine(line);
  return renderer.finish();
}

}  // namespace swingsim
