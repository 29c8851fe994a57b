#include "io/json_archive.h"

#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/input_error.h"

namespace swingsim {

JsonCheck<std::string> mustBeText(std::string expected) {
  return [expected = std::move(expected)](const std::string& v) {
    return v == expected ? std::string() : "\"" + expected + "\"";
  };
}

JsonCheck<std::uint64_t> mustBeWhole(std::uint64_t expected) {
  return [expected](const std::uint64_t& v) { return v == expected ? std::string() : std::to_string(expected); };
}

void failJsonFileKey(const std::string& path, const std::string& key, const std::string& expected,
                     const std::string& found) {
  throw InputError(path + ": " + key + ": expected " + expected + ", found " + found);
}

std::string describeJsonValue(const Json& v) {
  std::string s = v.dump();
  return s.size() > 60 ? s.substr(0, 57) + "..." : s;
}

Json parseJsonObject(const std::string& path, const std::string& text, const JsonFileKind& kind) {
  Json document;
  try {
    document = Json::parse(text);
  } catch (const Json::parse_error& e) {
    throw InputError(path + ": expected the JSON of " + kind.name + " (" + kind.writtenBy +
                     "), found text that is not JSON (" + e.what() + ")");
  }
  if (!document.is_object())
    throw InputError(path + ": expected a JSON object (" + kind.name + "), found " + describeJsonValue(document));
  return document;
}

// ---- Reading ---------------------------------------------------------------------------------

JsonReadArchive::JsonReadArchive(const std::string& path, const Json& object, const std::string& notComplete,
                                 std::string prefix)
    : path_(path), object_(object), notComplete_(notComplete), prefix_(std::move(prefix)) {}

void JsonReadArchive::fail(const std::string& key, const std::string& expected, const std::string& found) const {
  failJsonFileKey(path_, prefix_ + key, expected, found);
}

const Json& JsonReadArchive::at(const char* key) const {
  if (!object_.is_object() || !object_.contains(key)) fail(key, "the key (" + notComplete_ + ")", "it missing");
  return object_.at(key);
}

void JsonReadArchive::text(const char* key, std::string& v, const JsonCheck<std::string>& check) {
  const Json& value = at(key);
  if (!value.is_string()) fail(key, "a string", describeJsonValue(value));
  v = value.get<std::string>();
  if (!check) return;
  if (const std::string expected = check(v); !expected.empty()) fail(key, expected, describeJsonValue(value));
}

void JsonReadArchive::flag(const char* key, bool& v) {
  const Json& value = at(key);
  if (!value.is_boolean()) fail(key, "true or false", describeJsonValue(value));
  v = value.get<bool>();
}

std::uint64_t JsonReadArchive::readWhole(const char* key, std::uint64_t max,
                                         const JsonCheck<std::uint64_t>& check) const {
  const Json& value = at(key);
  if (!value.is_number_unsigned() || value.get<std::uint64_t>() > max)
    fail(key, "a whole number from 0 to " + std::to_string(max), describeJsonValue(value));
  const auto v = value.get<std::uint64_t>();
  if (!check) return v;
  if (const std::string expected = check(v); !expected.empty()) fail(key, expected, describeJsonValue(value));
  return v;
}

void JsonReadArchive::number(const char* key, double& v, const JsonCheck<double>& check) {
  const Json& value = at(key);
  if (value.is_null()) {
    v = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  if (!value.is_number()) fail(key, "a number or null", describeJsonValue(value));
  v = value.get<double>();
  if (!check) return;
  if (const std::string expected = check(v); !expected.empty()) fail(key, expected, describeJsonValue(value));
}

void JsonReadArchive::numbers(const char* key, std::vector<double>& v, const JsonCheck<double>& check) {
  const Json& list = at(key);
  if (!list.is_array()) fail(key, "a list of numbers", describeJsonValue(list));
  v.assign(list.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t k = 0; k < list.size(); ++k) {
    const Json& item = list[k];
    if (item.is_null()) continue;
    const std::string itemKey = std::string(key) + "[" + std::to_string(k) + "]";
    if (!item.is_number()) fail(itemKey, "a number or null", describeJsonValue(item));
    v[k] = item.get<double>();
    if (!check) continue;
    if (const std::string expected = check(v[k]); !expected.empty()) fail(itemKey, expected, describeJsonValue(item));
  }
}

void JsonReadArchive::wholeLines(const char* key, std::vector<std::uint64_t>& v,
                                 const JsonCheck<std::uint64_t>& check) {
  const Json& list = at(key);
  if (!list.is_array()) fail(key, "a list of whole numbers", describeJsonValue(list));
  v.resize(list.size());
  for (std::size_t k = 0; k < list.size(); ++k) {
    const Json& item = list[k];
    const std::string itemKey = std::string(key) + "[" + std::to_string(k) + "]";
    if (!item.is_number_unsigned()) fail(itemKey, "a whole number", describeJsonValue(item));
    v[k] = item.get<std::uint64_t>();
    if (!check) continue;
    if (const std::string expected = check(v[k]); !expected.empty()) fail(itemKey, expected, describeJsonValue(item));
  }
}

// ---- Writing ---------------------------------------------------------------------------------

namespace {

/// The separator before item `k` of a text list in an object `depth` deep.
std::string itemSeparator(std::size_t k, int depth) {
  return (k == 0 ? "\n" : ",\n") + std::string(2 * static_cast<std::size_t>(depth + 1), ' ');
}

}  // namespace

void JsonWriteArchive::number(const char* key, double v, const JsonCheck<double>&) {
  object_[key] = std::isfinite(v) ? Json(v) : Json(nullptr);
}

void JsonWriteArchive::numbers(const char* key, const std::vector<double>& v, const JsonCheck<double>&) {
  Json list = Json::array();
  for (double x : v) list.push_back(std::isfinite(x) ? Json(x) : Json(nullptr));
  object_[key] = std::move(list);
}

void JsonWriteArchive::numberLines(const char* key, const std::vector<double>& v, const JsonCheck<double>&) {
  const std::string first = itemSeparator(0, depth_), next = itemSeparator(1, depth_);
  std::string items;
  items.reserve((next.size() + 24) * v.size() + 8);
  char buf[40];
  for (std::size_t k = 0; k < v.size(); ++k) {
    // 17 significant digits read back to the same double.
    if (std::isfinite(v[k]))
      std::snprintf(buf, sizeof buf, "%.17g", v[k]);
    else
      std::snprintf(buf, sizeof buf, "null");
    items += k == 0 ? first : next;
    items += buf;
  }
  textList(key, std::move(items));
}

void JsonWriteArchive::wholeLines(const char* key, const std::vector<std::uint64_t>& v,
                                  const JsonCheck<std::uint64_t>&) {
  const std::string first = itemSeparator(0, depth_), next = itemSeparator(1, depth_);
  std::string items;
  char buf[24];
  for (std::size_t k = 0; k < v.size(); ++k) {
    std::snprintf(buf, sizeof buf, "%" PRIu64, v[k]);
    items += k == 0 ? first : next;
    items += buf;
  }
  textList(key, std::move(items));
}

void JsonWriteArchive::textList(const char* key, std::string items) {
  JsonTextList list;
  list.placeholder = std::string("@") + key + "@";
  list.items = std::move(items);
  list.depth = depth_;
  object_[key] = list.placeholder;
  lists_.push_back(std::move(list));
}

std::string formatJsonWithTextLists(const Json& document, const std::vector<JsonTextList>& lists) {
  std::string text = formatJson(document);
  std::size_t before = std::string::npos;
  for (auto list = lists.rbegin(); list != lists.rend(); ++list) {
    const std::string quoted = "\"" + list->placeholder + "\"";
    const std::size_t at = text.rfind(quoted, before);
    const std::string closing = "\n" + std::string(2 * static_cast<std::size_t>(list->depth), ' ') + "]";
    text.replace(at, quoted.size(), list->items.empty() ? "[]" : "[" + list->items + closing);
    before = at == 0 ? 0 : at - 1;
  }
  return text;
}

}  // namespace swingsim
