#include "io/yaml_reader.h"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "core/output_files.h"
#include "core/plausible_ranges.h"

namespace swingsim {

namespace {

std::string describe(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "nothing";
  if (node.IsScalar()) return "'" + node.Scalar() + "'";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a mapping";
  return "?";
}

// No input of ours comes near this many nodes; an alias of an alias of ... ("billion
// laughs") does, and walking it would take exponential time.
constexpr long kMaxYamlNodes = 1000000;
// Deepest nesting of maps and lists a file may have (ours nest 4 levels at most).
constexpr int kMaxYamlDepth = 64;

// Values written in the file (aliases counted once): our largest file has a few hundred.
// Counted on the parser's events before any node is built, so a long list under any key
// (known or not) is refused after reading this many values, not after building all of
// them (yaml-cpp spends a few hundred bytes a node: 16 MiB of "[0,0,..." would be GBs).
constexpr long kMaxYamlSourceNodes = 100000;

// Counts the parser's values and stops the parse at the limit.
class NodeCounter final : public YAML::EventHandler {
 public:
  explicit NodeCounter(const std::string& path) : path_(path) {}
  // yaml-cpp's Load reads the first document only: a second one would be silently ignored.
  void OnDocumentStart(const YAML::Mark& mark) override {
    if (++documents_ > 1)
      throw InputError(path_ + ":" + std::to_string(mark.line + 1) +
                       ": a second YAML document starts here (after a '---' line); a participant, model or study file "
                       "holds one document: merge the two or split them into two files");
  }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t) override { count(mark); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override { count(mark); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t, const std::string&) override {
    count(mark);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    count(mark);
    enter(mark);
  }
  void OnSequenceEnd() override { --depth_; }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    count(mark);
    enter(mark);
  }
  void OnMapEnd() override { --depth_; }

 private:
  void count(const YAML::Mark& mark) {
    if (++count_ > kMaxYamlSourceNodes) {
      throw InputError(path_ + ":" + std::to_string(mark.line + 1) + ": more than " +
                       std::to_string(kMaxYamlSourceNodes) +
                       " YAML values in one file (the limit; no participant, model or study file needs as many: "
                       "is a long list, perhaps under a misspelt key, pasted in by mistake?)");
    }
  }
  // Refused here, as the parser descends, before yaml-cpp's own recursion limit answers "bad file".
  void enter(const YAML::Mark& mark) {
    if (++depth_ > kMaxYamlDepth)
      throw InputError(path_ + ":" + std::to_string(mark.line + 1) + ": values nested more than " +
                       std::to_string(kMaxYamlDepth) + " levels deep (the limit; our files nest 4 levels at most)");
  }
  const std::string& path_;
  long count_ = 0;
  int depth_ = 0;
  int documents_ = 0;
};

// yaml-cpp keeps both entries of a duplicated key; a user who writes a key twice has
// made a mistake we must not paper over by silently taking one of them.
void rejectDuplicateKeys(const YAML::Node& node, const std::string& path, long& budget, int depth = 0) {
  // An alias inside the value it names (`key: &a [*a]`) makes a cycle that no depth ends;
  // no file of ours nests deeper than a few levels.
  if (depth > kMaxYamlDepth) {
    throw InputError(path + ":" + std::to_string(node.Mark().line + 1) + ": values nested more than " +
                     std::to_string(kMaxYamlDepth) +
                     " levels deep (does an alias (*name) refer to the value that holds it?)");
  }
  if (--budget < 0) {
    throw InputError(path + ":" + std::to_string(node.Mark().line + 1) + ": more than " +
                     std::to_string(kMaxYamlNodes) + " YAML values (do aliases (*name) refer to lists of aliases?)");
  }
  if (node.IsMap()) {
    std::set<std::string> seen;
    for (const auto& kv : node) {
      const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : "";
      // yaml-cpp 0.7 reads `<<: *base` as a key named "<<", not as a merge.
      if (key == "<<" && kv.first.Tag() != "!")
        throw InputError(path + ":" + std::to_string(kv.first.Mark().line + 1) +
                         ": <<: YAML merge keys are not supported (write the merged keys out in this mapping)");
      if (!seen.insert(key).second) {
        throw InputError(path + ":" + std::to_string(kv.first.Mark().line + 1) + ": " + key +
                         ": key appears twice in the same mapping");
      }
      rejectDuplicateKeys(kv.second, path, budget, depth + 1);
    }
  } else if (node.IsSequence()) {
    for (const auto& item : node) rejectDuplicateKeys(item, path, budget, depth + 1);
  }
}

YamlMap fromText(const std::string& text, const std::string& path) {
  YAML::Node root;
  try {
    // A UTF-8 byte-order mark is what spreadsheet and Windows editors write; accept it.
    std::string body = text;
    if (body.size() >= 3 && body.compare(0, 3, "\xEF\xBB\xBF") == 0) body.erase(0, 3);
    {
      std::istringstream in(body);
      YAML::Parser parser(in);
      NodeCounter counter(path);
      while (parser.HandleNextDocument(counter)) {
      }
    }
    root = YAML::Load(body);
  } catch (const YAML::Exception& e) {
    throw InputError(path + ":" + std::to_string(e.mark.line + 1) + ": YAML syntax error: " + e.msg);
  }
  if (!root.IsMap()) {
    throw InputError(path + ":1: expected a YAML mapping of keys (got " + describe(root) + ")");
  }
  long budget = kMaxYamlNodes;
  rejectDuplicateKeys(root, path, budget);
  return YamlMap(root, path);
}

}  // namespace

YamlMap YamlMap::loadFile(const std::string& path) { return fromText(readFile(path), path); }

YamlMap YamlMap::loadString(const std::string& text, const std::string& path) { return fromText(text, path); }

YamlMap::YamlMap(YAML::Node node, std::string path, std::string keyPrefix)
    : node_(std::move(node)), path_(std::move(path)), prefix_(std::move(keyPrefix)) {}

bool YamlMap::has(const std::string& key) const {
  if (std::find(used_.begin(), used_.end(), key) == used_.end()) used_.push_back(key);
  return node_[key].IsDefined() && !node_[key].IsNull();
}

int YamlMap::lineOf(const std::string& key) const {
  if (!key.empty()) {
    for (const auto& kv : node_) {
      if (kv.first.IsScalar() && kv.first.Scalar() == key) return kv.first.Mark().line + 1;
    }
  }
  return node_.Mark().line + 1;
}

std::string YamlMap::where(const std::string& key) const {
  std::string s = path_ + ":" + std::to_string(std::max(1, lineOf(key))) + ": ";
  if (!key.empty())
    s += prefix_ + key + ": ";
  else if (!prefix_.empty())
    s += prefix_.substr(0, prefix_.size() - 1) + ": ";
  return s;
}

void YamlMap::fail(const std::string& key, const std::string& what, const std::string& got) const {
  throw InputError(where(key) + what + " (got " + got + ")");
}

YAML::Node YamlMap::require(const std::string& key) const {
  if (std::find(used_.begin(), used_.end(), key) == used_.end()) used_.push_back(key);
  YAML::Node n = node_[key];
  if (!n.IsDefined()) {
    throw InputError(where() + (prefix_ + key) + ": required key is missing");
  }
  return n;
}

double YamlMap::toDouble(const YAML::Node& n, const std::string& key) const {
  if (!n.IsScalar()) fail(key, "expected a number", describe(n));
  const std::string& s = n.Scalar();
  // Spreadsheet exports with a comma decimal separator ("0,41") must not parse as 0.
  errno = 0;
  char* end = nullptr;
  double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size()) {
    std::string lower = s;
    std::transform(lower.begin(), lower.end(), lower.begin(), ::tolower);
    if (lower == ".nan" || lower == ".inf" || lower == "-.inf" || lower == "+.inf")
      fail(key, "expected a finite number", "'" + s + "'");
    if (s.find(',') != std::string::npos)
      fail(key, "expected a number with a decimal point, not a comma", "'" + s + "'");
    fail(key, "expected a number", "'" + s + "'");
  }
  if (!std::isfinite(v) || (errno == ERANGE && std::fabs(v) > 1)) fail(key, "expected a finite number", "'" + s + "'");
  if ((v != 0 || errno == ERANGE) && std::fabs(v) < kSmallestMagnitude) fail(key, kTooSmallMessage, "'" + s + "'");
  return v;
}

double YamlMap::getDouble(const std::string& key, const std::function<std::string(double)>& check) {
  YAML::Node n = require(key);
  double v = toDouble(n, key);
  if (check) {
    std::string what = check(v);
    if (!what.empty()) fail(key, what, formatNumber(v));
  }
  return v;
}

double YamlMap::getDouble(const std::string& key, double defaultValue,
                          const std::function<std::string(double)>& check) {
  if (!has(key)) return defaultValue;
  return getDouble(key, check);
}

int YamlMap::getInt(const std::string& key, int defaultValue) {
  if (!has(key)) return defaultValue;
  double v = toDouble(require(key), key);
  if (v != std::floor(v) || std::fabs(v) > 1e9) fail(key, "expected an integer", formatNumber(v));
  return static_cast<int>(v);
}

std::uint64_t YamlMap::getWhole(const std::string& key, std::uint64_t max, const std::string& range) {
  YAML::Node n = require(key);
  const std::string what = "expected an integer in [0, " + range + "]";
  if (!n.IsScalar()) fail(key, what, describe(n));
  const std::string& s = n.Scalar();
  if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos) {
    // 1e6 or 3.0: a whole number written otherwise, if a double holds it exactly.
    const double v = toDouble(n, key);
    constexpr double kExactDoubleLimit = 9007199254740992.0;  // 2^53
    if (v >= 0 && v == std::floor(v) && v <= kExactDoubleLimit && static_cast<std::uint64_t>(v) <= max)
      return static_cast<std::uint64_t>(v);
    fail(key, what, s);
  }
  errno = 0;
  const unsigned long long v = std::strtoull(s.c_str(), nullptr, 10);
  if (errno == ERANGE || v > max) fail(key, what, s);
  return static_cast<std::uint64_t>(v);
}

bool YamlMap::getBool(const std::string& key, bool defaultValue) {
  if (!has(key)) return defaultValue;
  YAML::Node n = require(key);
  if (n.IsScalar()) {
    const std::string& s = n.Scalar();
    if (s == "true" || s == "yes" || s == "True") return true;
    if (s == "false" || s == "no" || s == "False") return false;
  }
  fail(key, "expected true or false", describe(n));
}

std::string YamlMap::getString(const std::string& key) {
  YAML::Node n = require(key);
  if (!n.IsScalar() || n.Scalar().empty()) fail(key, "expected a text value", describe(n));
  return n.Scalar();
}

std::string YamlMap::getString(const std::string& key, const std::string& defaultValue) {
  if (!has(key)) return defaultValue;
  return getString(key);
}

std::string YamlMap::getChoice(const std::string& key, const std::vector<std::string>& allowed,
                               const std::string& defaultValue) {
  std::string v = defaultValue.empty() ? getString(key) : getString(key, defaultValue);
  if (std::find(allowed.begin(), allowed.end(), v) == allowed.end()) {
    std::string list;
    for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
    fail(key, "expected one of: " + list, "'" + v + "'");
  }
  return v;
}

std::vector<double> YamlMap::getDoubleList(const std::string& key) {
  YAML::Node n = require(key);
  if (!n.IsSequence()) fail(key, "expected a list of numbers", describe(n));
  std::vector<double> out;
  out.reserve(n.size());
  for (std::size_t i = 0; i < n.size(); ++i) {
    out.push_back(toDouble(n[i], key + "[" + std::to_string(i) + "]"));
  }
  return out;
}

std::vector<std::string> YamlMap::getStringList(const std::string& key) {
  YAML::Node n = require(key);
  if (!n.IsSequence()) fail(key, "expected a list of text values", describe(n));
  std::vector<std::string> out;
  for (std::size_t i = 0; i < n.size(); ++i) {
    if (!n[i].IsScalar()) fail(key + "[" + std::to_string(i) + "]", "expected a text value", describe(n[i]));
    out.push_back(n[i].Scalar());
  }
  return out;
}

YamlMap YamlMap::getMap(const std::string& key) {
  YAML::Node n = require(key);
  if (!n.IsMap()) fail(key, "expected a mapping of keys", describe(n));
  return YamlMap(n, path_, prefix_ + key + ".");
}

std::vector<YamlMap> YamlMap::getMapList(const std::string& key) {
  YAML::Node n = require(key);
  if (!n.IsSequence()) fail(key, "expected a list", describe(n));
  std::vector<YamlMap> out;
  for (std::size_t i = 0; i < n.size(); ++i) {
    if (!n[i].IsMap()) fail(key + "[" + std::to_string(i) + "]", "expected a mapping of keys", describe(n[i]));
    out.emplace_back(n[i], path_, prefix_ + key + "[" + std::to_string(i) + "].");
  }
  return out;
}

bool YamlMap::isMap(const std::string& key) const { return has(key) && node_[key].IsMap(); }

std::vector<std::string> YamlMap::keys() const {
  std::vector<std::string> out;
  for (const auto& kv : node_) out.push_back(kv.first.IsScalar() ? kv.first.Scalar() : "?");
  return out;
}

std::vector<YamlMap::TextOrMap> YamlMap::getTextOrMapList(const std::string& key, const std::string& textMeaning) {
  YAML::Node n = require(key);
  if (!n.IsSequence()) fail(key, "expected a list", describe(n));
  std::vector<TextOrMap> out;
  for (std::size_t i = 0; i < n.size(); ++i) {
    const std::string item = key + "[" + std::to_string(i) + "]";
    if (n[i].IsScalar())
      out.push_back({n[i].Scalar(), std::nullopt});
    else if (n[i].IsMap())
      out.push_back({"", YamlMap(n[i], path_, prefix_ + item + ".")});
    else
      fail(item, "expected " + textMeaning + " or a mapping of keys", describe(n[i]));
  }
  return out;
}

void YamlMap::finish() const {
  for (const auto& kv : node_) {
    const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : "?";
    if (std::find(used_.begin(), used_.end(), key) == used_.end()) {
      throw InputError(path_ + ":" + std::to_string(kv.first.Mark().line + 1) + ": " + prefix_ + key +
                       ": unknown key (check the spelling; see docs/formats.md)");
    }
  }
}

std::string YamlMap::directory() const {
  auto slash = path_.find_last_of('/');
  return slash == std::string::npos ? std::string(".") : path_.substr(0, slash);
}

std::string YamlMap::resolvePath(const std::string& relative, const std::string& key) const {
  if (!relative.empty() && relative[0] == '/') return relative;
  // Process substitution (`swingsim simulate <(cat p.yaml)`) reads /dev/fd/63, a pipe:
  // "next to it" would be /dev/fd/, which holds no model files.
  std::error_code ec;
  const auto type = std::filesystem::status(path_, ec).type();
  if (type == std::filesystem::file_type::fifo || type == std::filesystem::file_type::character ||
      type == std::filesystem::file_type::socket || path_.rfind("/dev/fd/", 0) == 0 || path_.rfind("/proc/", 0) == 0)
    throw InputError(where(key) + "relative path '" + relative + "' cannot be resolved next to " + path_ +
                     " (a pipe); give an absolute path or a file");
  return directory() + "/" + relative;
}

std::string mustBePositive(double v) { return v > 0 ? "" : "must be positive"; }
std::string mustBeNonNegative(double v) { return v >= 0 ? "" : "must not be negative"; }

}  // namespace swingsim
