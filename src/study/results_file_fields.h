#pragma once
// Reading the keys of one JSON object of a results file (cohort_results_file.h,
// uncertainty_swings_file.h), each failure an InputError `FILE: KEY: expected E, found F`.
#include <cstdint>
#include <string>
#include <vector>

#include "io/json_file.h"

namespace swingsim {

/// Throws InputError `PATH: KEY: expected EXPECTED, found FOUND`.
[[noreturn]] void failResultsFileKey(const std::string& path, const std::string& key, const std::string& expected,
                                     const std::string& found);
/// A JSON value as a message shows it: its JSON text, cut to 60 characters ("..." at the end).
std::string describeJsonValue(const Json& v);

/// The keys of one JSON object read from the results file at `path`; a key missing (or the
/// value not an object) fails with "expected the key (NOT_COMPLETE), found it missing".
/// Keys are named in messages with `prefix` before them ("shard.", "results[3].").
class ResultsFileFields {
 public:
  /// `notComplete` says what a missing key means ("this is not a complete cohort results
  /// file"). Keeps references: `path`, `object` and `notComplete` must outlive this.
  ResultsFileFields(const std::string& path, const Json& object, const std::string& notComplete,
                    std::string prefix = "");
  [[noreturn]] void fail(const std::string& key, const std::string& expected, const std::string& found) const;
  const Json& at(const std::string& key) const;
  std::string text(const std::string& key) const;
  bool flag(const std::string& key) const;
  /// A whole number from 0 to `max`.
  std::uint64_t whole(const std::string& key, std::uint64_t max) const;
  /// A number, or null for NaN.
  double number(const std::string& key) const;
  /// A list of numbers, null for NaN.
  std::vector<double> numbers(const std::string& key) const;

 private:
  const std::string& path_;
  const Json& object_;
  const std::string& notComplete_;
  std::string prefix_;
};

}  // namespace swingsim
