#include "study/results_file_fields.h"

#include <limits>
#include <utility>

#include "core/input_error.h"

namespace swingsim {

void failResultsFileKey(const std::string& path, const std::string& key, const std::string& expected,
                        const std::string& found) {
  throw InputError(path + ": " + key + ": expected " + expected + ", found " + found);
}

std::string describeJsonValue(const Json& v) {
  std::string s = v.dump();
  return s.size() > 60 ? s.substr(0, 57) + "..." : s;
}

ResultsFileFields::ResultsFileFields(const std::string& path, const Json& object, const std::string& notComplete,
                                     std::string prefix)
    : path_(path), object_(object), notComplete_(notComplete), prefix_(std::move(prefix)) {}

void ResultsFileFields::fail(const std::string& key, const std::string& expected, const std::string& found) const {
  failResultsFileKey(path_, prefix_ + key, expected, found);
}

const Json& ResultsFileFields::at(const std::string& key) const {
  if (!object_.is_object() || !object_.contains(key)) fail(key, "the key (" + notComplete_ + ")", "it missing");
  return object_.at(key);
}

std::string ResultsFileFields::text(const std::string& key) const {
  const Json& v = at(key);
  if (!v.is_string()) fail(key, "a string", describeJsonValue(v));
  return v.get<std::string>();
}

bool ResultsFileFields::flag(const std::string& key) const {
  const Json& v = at(key);
  if (!v.is_boolean()) fail(key, "true or false", describeJsonValue(v));
  return v.get<bool>();
}

std::uint64_t ResultsFileFields::whole(const std::string& key, std::uint64_t max) const {
  const Json& v = at(key);
  if (!v.is_number_unsigned() || v.get<std::uint64_t>() > max)
    fail(key, "a whole number from 0 to " + std::to_string(max), describeJsonValue(v));
  return v.get<std::uint64_t>();
}

double ResultsFileFields::number(const std::string& key) const {
  const Json& v = at(key);
  if (v.is_null()) return std::numeric_limits<double>::quiet_NaN();
  if (!v.is_number()) fail(key, "a number or null", describeJsonValue(v));
  return v.get<double>();
}

std::vector<double> ResultsFileFields::numbers(const std::string& key) const {
  const Json& v = at(key);
  if (!v.is_array()) fail(key, "a list of numbers", describeJsonValue(v));
  std::vector<double> out;
  for (const Json& x : v) {
    if (!x.is_null() && !x.is_number()) fail(key, "a list of numbers or nulls", describeJsonValue(x));
    out.push_back(x.is_null() ? std::numeric_limits<double>::quiet_NaN() : x.get<double>());
  }
  return out;
}

}  // namespace swingsim
