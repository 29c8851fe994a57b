#pragma once
// Each JSON results format is described once, as the YAML formats are (io/yaml_archive.h;
// Drake's Serialize(Archive*) pattern): a function `template <class Archive> void
// serialize(Archive& a, T& value)` lists the keys of T's JSON object in the order they are
// written, each with its check, and both archives walk that one list:
//   - JsonWriteArchive puts each key into an ordered Json object, written by formatJson
//     (io/json_file.h: 2-space indent), numbers in nlohmann's shortest form that reads back
//     to the same double; the long lists of numberLines/wholeLines are written as text,
//     one item a line (17 significant digits), not as a Json tree: about 25 bytes a swing
//     time instead of about 100 in memory, for files of millions of them;
//   - JsonReadArchive reads each key of one object of a file, every value typed and
//     checked, each failure an InputError `FILE: KEY: expected E, found F` where KEY names
//     the object it is in ("shard.index", "results[3].ran") and F is the value's JSON text;
//     a missing key is `expected the key (WHAT), found it missing`, WHAT saying what that
//     means ("this is not a complete cohort results file"); keys the list does not name are
//     ignored.
// Units: SI as inside, and a key in units says so by its suffix (swing_times_s,
// lowerings_m), so nothing is converted. A check returns "" for a value it accepts, else
// what was expected (the message's E). Checks that involve several keys are require(...)
// calls: the reader applies them, the writer skips them. A value the writer derives from
// others (a count, a checksum) is written from the record and, on reading, compared by a
// require with what the rest of the file gives.
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/output_files.h"
#include "io/json_file.h"

namespace swingsim {

/// A check of one value: "" if accepted, else what was expected ("a shard count of at
/// least 1").
template <class T>
using JsonCheck = std::function<std::string(const T&)>;

/// Accepts only `expected` (a format's name); the message quotes it.
JsonCheck<std::string> mustBeText(std::string expected);
/// Accepts only `expected` (a format's version).
JsonCheck<std::uint64_t> mustBeWhole(std::uint64_t expected);

/// Throws InputError `PATH: KEY: expected EXPECTED, found FOUND`.
[[noreturn]] void failJsonFileKey(const std::string& path, const std::string& key, const std::string& expected,
                                  const std::string& found);
/// A JSON value as a message shows it: its JSON text, cut to 60 characters ("..." at the end).
std::string describeJsonValue(const Json& v);

/// What kind of file a JSON file is meant to be, for the messages of its reader.
struct JsonFileKind {
  std::string name;         ///< "an uncertainty swings file"
  std::string writtenBy;    ///< what writes it: "sweep --shard or an interrupted sweep --uncertainty"
  std::string notComplete;  ///< what a missing key means: "this is not a complete cohort results file"
};

/// The JSON object in `text`, read from `path`. Throws InputError `PATH: expected the JSON
/// of NAME (WRITTEN_BY), found text that is not JSON (...)`, or `PATH: expected a JSON
/// object (NAME), found V` for JSON that is not an object.
Json parseJsonObject(const std::string& path, const std::string& text, const JsonFileKind& kind);

class JsonReadArchive {
 public:
  static constexpr bool kReading = true;
  /// Reads the keys of `object` (a value that is not an object has none) of the file at
  /// `path`, naming each key with `prefix` before it ("shard."). Keeps references: `path`,
  /// `object` and `notComplete` must outlive this.
  JsonReadArchive(const std::string& path, const Json& object, const std::string& notComplete, std::string prefix = "");

  /// Throws InputError `PATH: PREFIXKEY: expected EXPECTED, found FOUND`.
  [[noreturn]] void fail(const std::string& key, const std::string& expected, const std::string& found) const;

  /// A string.
  void text(const char* key, std::string& v, const JsonCheck<std::string>& check = {});
  void flag(const char* key, bool& v);
  /// A whole number from 0 to `max` (which must fit T).
  template <class T>
  void whole(const char* key, T& v, std::uint64_t max, const JsonCheck<std::uint64_t>& check = {}) {
    static_assert(std::is_integral_v<T>, "a whole number is read into an integer");
    assert(max <= static_cast<std::uint64_t>(std::numeric_limits<T>::max()));  // the format's own bound
    v = static_cast<T>(readWhole(key, max, check));
  }
  /// A number, or null for NaN (a quantity that does not exist); `check` applies to a number.
  void number(const char* key, double& v, const JsonCheck<double>& check = {});
  /// A list of numbers, null for NaN; `check` applies to each number.
  void numbers(const char* key, std::vector<double>& v, const JsonCheck<double>& check = {});
  /// As numbers(); the writer writes the list as text (for lists of millions).
  void numberLines(const char* key, std::vector<double>& v, const JsonCheck<double>& check = {}) {
    numbers(key, v, check);
  }
  /// A list of whole numbers, written as text; `check` applies to each.
  void wholeLines(const char* key, std::vector<std::uint64_t>& v, const JsonCheck<std::uint64_t>& check = {});
  /// An object read through serialize(a, v, context...), or null (then `present` is false
  /// and `v` is left as it is); `shape` describes the object for a message ("{"index": K,
  /// "count": N}").
  template <class T, class... Context>
  void nullOrObject(const char* key, T& v, bool& present, const std::string& shape, Context&&... context) {
    const Json& value = at(key);
    present = !value.is_null();
    if (!present) return;
    if (!value.is_object()) fail(key, "null or " + shape, describeJsonValue(value));
    JsonReadArchive child(path_, value, notComplete_, prefix_ + key + ".");
    serialize(child, v, std::forward<Context>(context)...);
  }
  /// A list of objects, item k read through serialize(a, v[k], k, context...).
  template <class T, class... Context>
  void objectList(const char* key, std::vector<T>& v, Context&&... context) {
    const Json& list = at(key);
    if (!list.is_array()) fail(key, "a list of objects", describeJsonValue(list));
    v.clear();
    v.reserve(list.size());
    for (std::size_t k = 0; k < list.size(); ++k) {
      JsonReadArchive child(path_, list[k], notComplete_, prefix_ + key + "[" + std::to_string(k) + "].");
      v.emplace_back();
      serialize(child, v.back(), k, context...);
    }
  }
  /// A check across keys: fails with `FILE: KEY: expected EXPECTED, found FOUND()` unless `ok`.
  void require(bool ok, const char* key, const std::string& expected, const std::function<std::string()>& found) const {
    if (!ok) fail(key, expected, found());
  }

 private:
  const Json& at(const char* key) const;
  std::uint64_t readWhole(const char* key, std::uint64_t max, const JsonCheck<std::uint64_t>& check) const;
  const std::string& path_;
  const Json& object_;
  const std::string& notComplete_;
  std::string prefix_;
};

/// A list the writer puts into the document's text itself (numberLines, wholeLines).
struct JsonTextList {
  std::string placeholder;  ///< the string that stands for it in the Json tree
  std::string items;        ///< its items, each after ",\n" and its indent
  int depth = 1;            ///< nesting depth of the object holding it (the document's is 1)
};

/// formatJson(document), each of `lists` put in place of its placeholder (the last one in
/// the text, the lists taken from the last: a list's key comes after every value written
/// before it).
std::string formatJsonWithTextLists(const Json& document, const std::vector<JsonTextList>& lists);

class JsonWriteArchive {
 public:
  static constexpr bool kReading = false;
  /// Writes keys into `object` (nested `depth` deep: the document is 1); lists written as
  /// text go to `lists`.
  JsonWriteArchive(Json& object, std::vector<JsonTextList>& lists, int depth = 1)
      : object_(object), lists_(lists), depth_(depth) {}

  void text(const char* key, const std::string& v, const JsonCheck<std::string>& = {}) { object_[key] = v; }
  void flag(const char* key, bool v) { object_[key] = v; }
  template <class T>
  void whole(const char* key, T v, std::uint64_t, const JsonCheck<std::uint64_t>& = {}) {
    object_[key] = v;
  }
  void number(const char* key, double v, const JsonCheck<double>& = {});
  void numbers(const char* key, const std::vector<double>& v, const JsonCheck<double>& = {});
  /// 17 significant digits, null where not finite.
  void numberLines(const char* key, const std::vector<double>& v, const JsonCheck<double>& = {});
  void wholeLines(const char* key, const std::vector<std::uint64_t>& v, const JsonCheck<std::uint64_t>& = {});
  template <class T, class... Context>
  void nullOrObject(const char* key, T& v, bool present, const std::string&, Context&&... context) {
    if (!present) {
      object_[key] = nullptr;
      return;
    }
    Json child = Json::object();
    JsonWriteArchive a(child, lists_, depth_ + 1);
    serialize(a, v, std::forward<Context>(context)...);
    object_[key] = std::move(child);
  }
  template <class T, class... Context>
  void objectList(const char* key, std::vector<T>& v, Context&&... context) {
    Json list = Json::array();
    for (std::size_t k = 0; k < v.size(); ++k) {
      Json child = Json::object();
      JsonWriteArchive a(child, lists_, depth_ + 2);  // inside the list inside this object
      serialize(a, v[k], k, context...);
      list.push_back(std::move(child));
    }
    object_[key] = std::move(list);
  }
  void require(bool, const char*, const std::string&, const std::function<std::string()>&) const {}

 private:
  void textList(const char* key, std::string items);
  Json& object_;
  std::vector<JsonTextList>& lists_;
  int depth_;
};

/// The JSON text of `value` (ending in a newline) through its serialize().
template <class T, class... Context>
std::string formatJsonDocument(const T& value, Context&&... context) {
  Json document = Json::object();
  std::vector<JsonTextList> lists;
  JsonWriteArchive a(document, lists);
  // The writer only reads: serialize() takes the value non-const to serve the reader too
  // (as Drake's YamlWriteArchive::Accept does).
  serialize(a, const_cast<T&>(value), std::forward<Context>(context)...);
  return formatJsonWithTextLists(document, lists);
}

/// Reads the file at `path` (at most `maxBytes`, core/output_files.h) into `value` through
/// its serialize(). Throws InputError naming the file, and the key, what was expected and
/// what was found.
template <class T, class... Context>
void readJsonDocument(const std::string& path, std::size_t maxBytes, const JsonFileKind& kind, T& value,
                      Context&&... context) {
  const Json document = parseJsonObject(path, readFile(path, maxBytes), kind);
  JsonReadArchive a(path, document, kind.notComplete);
  serialize(a, value, std::forward<Context>(context)...);
}

}  // namespace swingsim
