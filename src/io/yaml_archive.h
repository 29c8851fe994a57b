#pragma once
// Each YAML file format is described once (Drake's Serialize(Archive*) pattern,
// drake/common/yaml/yaml_io.h): a function `template <class Archive> void serialize(Archive&
// a, T& value)` lists the fields of T with their keys, units and checks, and both archives
// walk that one list:
//   - YamlReadArchive reads through YamlMap: every key known, every value typed and
//     checked, errors as `file:line: key: what is wrong (got VALUE)`, unknown keys rejected;
//   - YamlWriteArchive writes with yaml-cpp's emitter, numbers in their shortest form that
//     reads back to the same double.
// Keys ending in _deg hold radians inside and degrees in the file (angle()). Checks that
// involve several fields are `require(...)` calls: the reader applies them, the writer
// (which writes what was read) skips them.
#include <yaml-cpp/yaml.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/input_error.h"
#include "core/plausible_ranges.h"
#include "core/units.h"
#include "io/yaml_reader.h"

namespace swingsim {

using ValueCheck = std::function<std::string(double)>;

/// The check of a value against its plausible range (core/plausible_ranges.h); `what` names
/// the quantity in the message ("an initial knee angle").
inline ValueCheck mustBePlausible(const PlausibleRange& range, std::string what) {
  return [range, what = std::move(what)](double v) { return checkPlausible(v, range, what); };
}

/// The shortest decimal degrees that read back (times kDegToRad) to exactly `radians`.
std::string formatDegrees(double radians);

class YamlReadArchive {
 public:
  static constexpr bool kReading = true;
  explicit YamlReadArchive(YamlMap& map) : map_(map) {}

  YamlMap& yaml() { return map_; }
  bool has(const char* key) const { return map_.has(key); }

  /// Required number.
  void number(const char* key, double& v, const ValueCheck& check = {}) { v = map_.getDouble(key, check); }
  /// Optional number: `v` holds its default on entry.
  void optionalNumber(const char* key, double& v, const ValueCheck& check = {}) { v = map_.getDouble(key, v, check); }
  /// Required angle: radians in `v`, degrees in the file (`key` ends in _deg).
  void angle(const char* key, double& v, const ValueCheck& checkDeg = {}) {
    v = map_.getDouble(key, checkDeg) * kDegToRad;
  }
  /// Optional angle: `v` (rad) holds its default on entry.
  void optionalAngle(const char* key, double& v, const ValueCheck& checkDeg = {}) {
    v = map_.getDouble(key, v * kRadToDeg, checkDeg) * kDegToRad;
  }
  void integer(const char* key, int& v) {
    if (!map_.has(key)) map_.getDouble(key);  // "required key is missing"
    v = map_.getInt(key, v);
  }
  /// Optional whole number: `v` holds its default on entry.
  void optionalInteger(const char* key, int& v) { v = map_.getInt(key, v); }
  /// Required whole number from 0 to `max`, exact (YamlMap::getWhole; `range` names max).
  void whole(const char* key, std::uint64_t& v, std::uint64_t max, const std::string& range) {
    v = map_.getWhole(key, max, range);
  }
  void optionalFlag(const char* key, bool& v) { v = map_.getBool(key, v); }
  void text(const char* key, std::string& v) { v = map_.getString(key); }
  void optionalText(const char* key, std::string& v) { v = map_.getString(key, v); }
  /// A path in the file, relative to the file's folder; resolved on reading.
  void path(const char* key, std::string& v) { v = map_.resolvePath(map_.getString(key), key); }
  void numbers(const char* key, std::vector<double>& v) { v = map_.getDoubleList(key); }
  /// A list of angles: radians in `v`, degrees in the file.
  void angles(const char* key, std::vector<double>& v) {
    v = map_.getDoubleList(key);
    for (double& x : v) x *= kDegToRad;
  }
  void texts(const char* key, std::vector<std::string>& v) { v = map_.getStringList(key); }
  /// A list of paths, each resolved against the file's folder.
  void paths(const char* key, std::vector<std::string>& v) {
    v.clear();
    for (const auto& p : map_.getStringList(key)) v.push_back(map_.resolvePath(p, key));
  }
  /// An enum written as one of `names` (same order as `values`); `optional`: `v` holds its
  /// default on entry.
  template <class E>
  void choice(const char* key, E& v, const std::vector<std::pair<std::string, E>>& options, bool optional = false) {
    std::vector<std::string> names;
    std::string current;
    for (const auto& [name, value] : options) {
      names.push_back(name);
      if (value == v) current = name;
    }
    const std::string got = map_.getChoice(key, names, optional ? current : "");
    for (const auto& [name, value] : options)
      if (name == got) v = value;
  }
  /// A nested map, required.
  template <class T, class... Context>
  void map(const char* key, T& v, Context&&... context) {
    YamlMap child = map_.getMap(key);
    YamlReadArchive a(child);
    serialize(a, v, std::forward<Context>(context)...);
    child.finish();
  }
  /// A nested map written in flow style ({a: 1, b: 2}) by the writer.
  template <class T, class... Context>
  void flowMap(const char* key, T& v, Context&&... context) {
    map(key, v, std::forward<Context>(context)...);
  }
  /// A nested map that may be absent (then `v` keeps its defaults); `present` says which.
  template <class T, class... Context>
  void optionalMap(const char* key, T& v, bool& present, Context&&... context) {
    present = map_.has(key);
    if (present) map(key, v, std::forward<Context>(context)...);
  }
  /// A list of nested maps.
  template <class T, class... Context>
  void mapList(const char* key, std::vector<T>& v, Context&&... context) {
    v.clear();
    for (YamlMap& child : map_.getMapList(key)) {
      YamlReadArchive a(child);
      v.emplace_back();
      serialize(a, v.back(), std::forward<Context>(context)...);
      child.finish();
    }
  }
  /// A list whose items are each a path (stored in `v[i].*path`, resolved) or a mapping
  /// read through serialize(); `isPlain` is the writer's choice between the two.
  template <class T>
  void pathOrMapList(const char* key, std::vector<T>& v, std::string T::*path, bool (*isPlain)(const T&)) {
    (void)isPlain;
    v.clear();
    for (auto& item : map_.getTextOrMapList(key)) {
      v.emplace_back();
      if (!item.map) {
        v.back().*path = map_.resolvePath(item.text, key);
        continue;
      }
      YamlReadArchive a(*item.map);
      serialize(a, v.back());
      item.map->finish();
    }
  }
  /// A list whose items are each a text value (stored in `v[i].*text`, not resolved as a
  /// path) or a mapping read through serialize(); `isPlain` is the writer's choice.
  template <class T>
  void textOrMapList(const char* key, std::vector<T>& v, std::string T::*text, bool (*isPlain)(const T&),
                     const std::string& textMeaning) {
    (void)isPlain;
    v.clear();
    for (auto& item : map_.getTextOrMapList(key, textMeaning)) {
      v.emplace_back();
      if (!item.map) {
        v.back().*text = item.text;
        continue;
      }
      YamlReadArchive a(*item.map);
      serialize(a, v.back());
      item.map->finish();
    }
  }
  /// A mapping of named mappings ({c: {unit: N m, min: 0}}): one T each, in the file's order,
  /// its key stored in `v[i].*name`.
  template <class T>
  void namedMaps(const char* key, std::vector<T>& v, std::string T::*name) {
    v.clear();
    YamlMap outer = map_.getMap(key);
    for (const std::string& k : outer.keys()) {
      YamlMap child = outer.getMap(k);
      YamlReadArchive a(child);
      v.emplace_back();
      v.back().*name = k;
      serialize(a, v.back());
      child.finish();
    }
  }
  /// A check across fields: fails with `file:line: key: what (got GOT)` unless `ok`.
  void require(bool ok, const char* key, const std::string& what, const std::function<std::string()>& got) {
    if (!ok) map_.fail(key, what, got());
  }

 private:
  YamlMap& map_;
};

class YamlWriteArchive {
 public:
  static constexpr bool kReading = false;
  /// Writes into `out` (inside a map); paths are written relative to `baseDir` (the folder
  /// of the file being written) when they lie below it, else absolute.
  YamlWriteArchive(YAML::Emitter& out, std::string baseDir) : out_(out), baseDir_(std::move(baseDir)) {}

  void number(const char* key, double& v, const ValueCheck& = {}) { scalar(key, formatNumber(v)); }
  void optionalNumber(const char* key, double& v, const ValueCheck& = {}) { scalar(key, formatNumber(v)); }
  void angle(const char* key, double& v, const ValueCheck& = {}) { scalar(key, formatDegrees(v)); }
  void optionalAngle(const char* key, double& v, const ValueCheck& = {}) { scalar(key, formatDegrees(v)); }
  void integer(const char* key, int& v) { scalar(key, std::to_string(v)); }
  void optionalInteger(const char* key, int& v) { scalar(key, std::to_string(v)); }
  void whole(const char* key, std::uint64_t& v, std::uint64_t, const std::string&) { scalar(key, std::to_string(v)); }
  void optionalFlag(const char* key, bool& v) { scalar(key, v ? "true" : "false"); }
  void text(const char* key, std::string& v) { out_ << YAML::Key << key << YAML::Value << v; }
  void optionalText(const char* key, std::string& v) {
    if (!v.empty()) text(key, v);
  }
  void path(const char* key, std::string& v) { out_ << YAML::Key << key << YAML::Value << relative(v); }
  void numbers(const char* key, std::vector<double>& v) {
    out_ << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq;
    for (double x : v) out_ << formatNumber(x);
    out_ << YAML::EndSeq;
  }
  void angles(const char* key, std::vector<double>& v) {
    out_ << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq;
    for (double x : v) out_ << formatDegrees(x);
    out_ << YAML::EndSeq;
  }
  void texts(const char* key, std::vector<std::string>& v) {
    out_ << YAML::Key << key << YAML::Value << YAML::BeginSeq;
    for (const auto& x : v) out_ << x;
    out_ << YAML::EndSeq;
  }
  void paths(const char* key, std::vector<std::string>& v) {
    out_ << YAML::Key << key << YAML::Value << YAML::BeginSeq;
    for (const auto& x : v) out_ << relative(x);
    out_ << YAML::EndSeq;
  }
  template <class E>
  void choice(const char* key, E& v, const std::vector<std::pair<std::string, E>>& options, bool = false) {
    for (const auto& [name, value] : options)
      if (value == v) out_ << YAML::Key << key << YAML::Value << name;
  }
  template <class T, class... Context>
  void map(const char* key, T& v, Context&&... context) {
    out_ << YAML::Key << key << YAML::Value << YAML::BeginMap;
    serialize(*this, v, std::forward<Context>(context)...);
    out_ << YAML::EndMap;
  }
  template <class T, class... Context>
  void flowMap(const char* key, T& v, Context&&... context) {
    out_ << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginMap;
    serialize(*this, v, std::forward<Context>(context)...);
    out_ << YAML::EndMap;
  }
  template <class T, class... Context>
  void optionalMap(const char* key, T& v, bool& present, Context&&... context) {
    if (present) map(key, v, std::forward<Context>(context)...);
  }
  template <class T, class... Context>
  void mapList(const char* key, std::vector<T>& v, Context&&... context) {
    out_ << YAML::Key << key << YAML::Value << YAML::BeginSeq;
    for (auto& item : v) {
      out_ << YAML::BeginMap;
      serialize(*this, item, std::forward<Context>(context)...);
      out_ << YAML::EndMap;
    }
    out_ << YAML::EndSeq;
  }
  template <class T>
  void pathOrMapList(const char* key, std::vector<T>& v, std::string T::*path, bool (*isPlain)(const T&)) {
    out_ << YAML::Key << key << YAML::Value << YAML::BeginSeq;
    for (auto& item : v) {
      if (isPlain(item)) {
        out_ << relative(item.*path);
        continue;
      }
      out_ << YAML::Flow << YAML::BeginMap;
      serialize(*this, item);
      out_ << YAML::EndMap;
    }
    out_ << YAML::EndSeq;
  }
  template <class T>
  void textOrMapList(const char* key, std::vector<T>& v, std::string T::*text, bool (*isPlain)(const T&),
                     const std::string&) {
    out_ << YAML::Key << key << YAML::Value << YAML::BeginSeq;
    for (auto& item : v) {
      if (isPlain(item)) {
        out_ << item.*text;
        continue;
      }
      out_ << YAML::BeginMap;
      serialize(*this, item);
      out_ << YAML::EndMap;
    }
    out_ << YAML::EndSeq;
  }
  template <class T>
  void namedMaps(const char* key, std::vector<T>& v, std::string T::*name) {
    out_ << YAML::Key << key << YAML::Value << YAML::BeginMap;
    for (auto& item : v) {
      out_ << YAML::Key << item.*name << YAML::Value << YAML::Flow << YAML::BeginMap;
      serialize(*this, item);
      out_ << YAML::EndMap;
    }
    out_ << YAML::EndMap;
  }
  void require(bool, const char*, const std::string&, const std::function<std::string()>&) {}

 private:
  void scalar(const char* key, const std::string& v) { out_ << YAML::Key << key << YAML::Value << v; }
  std::string relative(const std::string& path) const;
  YAML::Emitter& out_;
  std::string baseDir_;
};

/// Emits `value` as a whole YAML document through its serialize(); `baseDir` as for
/// YamlWriteArchive. `header` lines (without '#') are written first as comments.
template <class T, class... Context>
std::string writeYamlDocument(T value, const std::string& baseDir, const std::string& header, Context&&... context) {
  YAML::Emitter out;
  out << YAML::BeginMap;
  YamlWriteArchive a(out, baseDir);
  serialize(a, value, std::forward<Context>(context)...);
  out << YAML::EndMap;
  std::string text;
  std::size_t start = 0;
  while (!header.empty() && start <= header.size()) {
    const std::size_t end = header.find('\n', start);
    text += "# " + header.substr(start, end == std::string::npos ? std::string::npos : end - start) + "\n";
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return text + out.c_str() + "\n";
}

}  // namespace swingsim
