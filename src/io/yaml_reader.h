#pragma once
// Strict YAML reading: every key known, every value typed and checked, every error
// located as `file:line: key: what is wrong (got VALUE)`.
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include "core/input_error.h"

namespace swingsim {

/// A YAML mapping node together with the file it came from, so that every accessor can
/// report `file:line`. Construct from a file with `YamlMap::loadFile`. Each accessor
/// records the key as used; `finish()` rejects keys that were never asked for.
class YamlMap {
 public:
  /// Parses a file whose top level must be a mapping. Throws InputError on a missing
  /// file, a syntax error (with the line), duplicated keys, or a non-mapping top level.
  static YamlMap loadFile(const std::string& path);
  /// Parses YAML text (for tests and fuzzers); `path` is used in messages only.
  static YamlMap loadString(const std::string& text, const std::string& path);

  YamlMap(YAML::Node node, std::string path, std::string keyPrefix = "");

  bool has(const std::string& key) const;

  /// Required finite number; `check` (optional) returns an empty string if the value is
  /// fine or a description of what is wrong ("must be positive").
  double getDouble(const std::string& key, const std::function<std::string(double)>& check = {});
  double getDouble(const std::string& key, double defaultValue, const std::function<std::string(double)>& check = {});
  int getInt(const std::string& key, int defaultValue);
  /// Required whole number from 0 to `max`, read exactly (digits, no rounding through a
  /// double): a seed. Fails with `expected an integer in [0, RANGE] (got VALUE)`, `range`
  /// naming the upper end as the reader should see it ("2^64 - 1 = 18446744073709551615").
  std::uint64_t getWhole(const std::string& key, std::uint64_t max, const std::string& range);
  bool getBool(const std::string& key, bool defaultValue);
  std::string getString(const std::string& key);
  std::string getString(const std::string& key, const std::string& defaultValue);
  /// A string that must be one of `allowed`.
  std::string getChoice(const std::string& key, const std::vector<std::string>& allowed,
                        const std::string& defaultValue);
  std::vector<double> getDoubleList(const std::string& key);
  std::vector<std::string> getStringList(const std::string& key);
  /// A nested mapping.
  YamlMap getMap(const std::string& key);
  /// A list of nested mappings.
  std::vector<YamlMap> getMapList(const std::string& key);
  /// Whether `key` holds a mapping (false if absent or another kind of value).
  bool isMap(const std::string& key) const;
  /// One item of a list whose items are each a text value or a mapping.
  struct TextOrMap;
  /// A list whose items are each a text value (`textMeaning` in messages) or a mapping.
  std::vector<TextOrMap> getTextOrMapList(const std::string& key, const std::string& textMeaning = "a file name");
  /// The keys of the mapping, in the file's order (none is marked used).
  std::vector<std::string> keys() const;

  /// Throws if the mapping holds a key that no accessor asked for.
  void finish() const;

  /// `file:line: key: ` prefix for messages about `key` (or the map itself if empty).
  std::string where(const std::string& key = "") const;
  [[noreturn]] void fail(const std::string& key, const std::string& what, const std::string& got) const;

  const std::string& path() const { return path_; }
  /// Directory of the file, for resolving relative paths in it.
  std::string directory() const;
  /// Resolves `relative`, the value of `key`, against the file's directory (absolute paths
  /// pass through). InputError naming `key` if the file is a pipe (`<(cat file)` is
  /// /dev/fd/63): it has no directory to resolve against.
  std::string resolvePath(const std::string& relative, const std::string& key = "") const;
  /// Line (1-based) of `key` in the file, or of the map itself.
  int lineOf(const std::string& key) const;

 private:
  YAML::Node require(const std::string& key) const;
  double toDouble(const YAML::Node& node, const std::string& key) const;

  YAML::Node node_;
  std::string path_;
  std::string prefix_;
  mutable std::vector<std::string> used_;
};

struct YamlMap::TextOrMap {
  std::string text;            ///< the item, if it is a text value
  std::optional<YamlMap> map;  ///< the item, if it is a mapping
};

/// Common value checks for getDouble.
std::string mustBePositive(double v);
std::string mustBeNonNegative(double v);

}  // namespace swingsim
