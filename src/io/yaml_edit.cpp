#include "io/yaml_edit.h"

#include <sstream>
#include <vector>

#include "core/input_error.h"

namespace swingsim {

std::string setNestedScalar(const std::string& text, const std::string& path, const std::string& block,
                            const std::string& key, const std::string& value) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  std::size_t start = lines.size();
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].compare(0, block.size() + 1, block + ":") == 0) {
      start = i;
      break;
    }
  }
  if (start == lines.size()) throw InputError(path + ": " + block + ": block not found, cannot store " + key);
  std::size_t insertAt = start + 1;
  for (std::size_t i = start + 1; i < lines.size(); ++i) {
    const std::string& l = lines[i];
    if (l.empty() || l[0] == '#') continue;
    if (l[0] != ' ') break;  // next top-level key: end of the block
    const auto first = l.find_first_not_of(' ');
    if (l.compare(first, key.size() + 1, key + ":") == 0) {
      const auto hash = l.find(" #");
      std::string comment = hash == std::string::npos ? "" : l.substr(hash);
      std::string head = l.substr(0, first) + key + ": " + value;
      if (!comment.empty() && head.size() < 32) head.resize(32, ' ');
      lines[i] = head + comment;
      std::string out;
      for (const auto& x : lines) out += x + "\n";
      return out;
    }
    insertAt = i + 1;
  }
  lines.insert(lines.begin() + static_cast<long>(start + 1), "  " + key + ": " + value);
  (void)insertAt;
  std::string out;
  for (const auto& x : lines) out += x + "\n";
  return out;
}

}  // namespace swingsim
