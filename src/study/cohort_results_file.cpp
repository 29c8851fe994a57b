#include "study/cohort_results_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>

#include "core/input_error.h"
#include "core/output_files.h"
#include "io/json_file.h"
#include "study/uncertainty_swings_file.h"

namespace swingsim {

namespace {

constexpr const char* kFormat = "swingsim cohort results";
constexpr int kFormatVersion = 1;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// The largest cohort (100,000 participants of a few dozen swing times each, about 30 bytes a
// number as JSON) is far above the 16 MiB of an input file.
constexpr std::size_t kMaxResultsFileBytes = std::size_t{512} << 20;

[[noreturn]] void fail(const std::string& path, const std::string& key, const std::string& expected,
                       const std::string& found) {
  throw InputError(path + ": " + key + ": expected " + expected + ", found " + found);
}

std::string describe(const Json& v) {
  std::string s = v.dump();
  return s.size() > 60 ? s.substr(0, 57) + "..." : s;
}

/// Reads keys of one JSON object of a results file, failing with file: key: expected, found.
class Fields {
 public:
  Fields(const std::string& path, const Json& object, std::string prefix = "")
      : path_(path), object_(object), prefix_(std::move(prefix)) {}
  const Json& at(const std::string& key) const {
    if (!object_.is_object() || !object_.contains(key))
      fail(path_, prefix_ + key, "the key (this is not a complete cohort results file)", "it missing");
    return object_.at(key);
  }
  std::string text(const std::string& key) const {
    const Json& v = at(key);
    if (!v.is_string()) fail(path_, prefix_ + key, "a string", describe(v));
    return v.get<std::string>();
  }
  bool flag(const std::string& key) const {
    const Json& v = at(key);
    if (!v.is_boolean()) fail(path_, prefix_ + key, "true or false", describe(v));
    return v.get<bool>();
  }
  std::uint64_t whole(const std::string& key, std::uint64_t max) const {
    const Json& v = at(key);
    if (!v.is_number_unsigned() || v.get<std::uint64_t>() > max)
      fail(path_, prefix_ + key, "a whole number from 0 to " + std::to_string(max), describe(v));
    return v.get<std::uint64_t>();
  }
  /// A number, or null for NaN.
  double number(const std::string& key) const {
    const Json& v = at(key);
    if (v.is_null()) return kNaN;
    if (!v.is_number()) fail(path_, prefix_ + key, "a number or null", describe(v));
    return v.get<double>();
  }
  std::vector<double> numbers(const std::string& key) const {
    const Json& v = at(key);
    if (!v.is_array()) fail(path_, prefix_ + key, "a list of numbers", describe(v));
    std::vector<double> out;
    for (const Json& x : v) {
      if (!x.is_null() && !x.is_number()) fail(path_, prefix_ + key, "a list of numbers or nulls", describe(x));
      out.push_back(x.is_null() ? kNaN : x.get<double>());
    }
    return out;
  }

 private:
  const std::string& path_;
  const Json& object_;
  std::string prefix_;
};

Json formatNumberOrNull(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

Json formatResult(const std::string& name, const CohortParticipantResult& r) {
  Json j;
  j["participant"] = name;
  j["ran"] = r.ran;
  if (!r.ran) return j;
  j["calibrated"] = r.calibrated;
  j["failure"] = r.failure;
  j["time_scale"] = formatNumberOrNull(r.timeScale);
  j["calibration_swings"] = r.calibrationSwings;
  Json lowerings = Json::array(), times = Json::array();
  for (double d : r.sweep.lowerings) lowerings.push_back(d);
  for (double t : r.sweep.swingTimes) times.push_back(formatNumberOrNull(t));
  j["lowerings_m"] = lowerings;
  j["swing_times_s"] = times;
  return j;
}

CohortParticipantResult readResult(const std::string& path, const Json& j, const std::string& prefix) {
  const Fields f(path, j, prefix);
  CohortParticipantResult r;
  r.ran = f.flag("ran");
  if (!r.ran) return r;
  r.calibrated = f.flag("calibrated");
  r.failure = f.text("failure");
  r.timeScale = f.number("time_scale");
  r.calibrationSwings = static_cast<int>(f.whole("calibration_swings", 1000000));
  r.sweep.lowerings = f.numbers("lowerings_m");
  r.sweep.swingTimes = f.numbers("swing_times_s");
  if (r.sweep.lowerings.size() != r.sweep.swingTimes.size())
    fail(path, prefix + "swing_times_s", "one swing time per lowering (" + std::to_string(r.sweep.lowerings.size()) + ")",
         std::to_string(r.sweep.swingTimes.size()));
  pickBest(r.sweep);
  return r;
}

}  // namespace

std::size_t CohortResultsFile::countFinished() const {
  return static_cast<std::size_t>(
      std::count_if(results.begin(), results.end(), [](const CohortParticipantResult& r) { return r.ran; }));
}

CohortRunIdentity makeCohortRunIdentity(const Cohort& cohort, const std::string& version) {
  CohortRunIdentity id;
  id.study = cohort.study.name;
  id.studyPath = cohort.study.path;  // as given: merge loads it from there
  id.inputsFingerprint = calcStudyInputsFingerprint(cohort.study);
  id.participants = cohort.count;
  id.seed = cohort.seed;
  id.version = version;
  return id;
}

std::string formatCohortResultsJson(const CohortResultsFile& file) {
  Json j;
  j["format"] = kFormat;
  j["format_version"] = kFormatVersion;
  j["partial"] = file.isPartial();
  j["study"] = file.run.study;
  j["study_path"] = file.run.studyPath;
  j["swingsim_version"] = file.run.version;
  j["inputs_fingerprint"] = file.run.inputsFingerprint;
  j["participants"] = file.run.participants;
  j["seed"] = file.run.seed;
  if (file.sharded)
    j["shard"] = {{"index", file.shardIndex}, {"count", file.shardCount}};
  else
    j["shard"] = nullptr;
  j["first_participant"] = file.first;
  j["last_participant"] = file.last;
  j["participants_finished"] = file.countFinished();
  Json results = Json::array();
  for (std::size_t k = 0; k < file.results.size(); ++k)
    results.push_back(formatResult(cohortParticipantName(file.first + k, static_cast<std::size_t>(file.run.participants)),
                                   file.results[k]));
  j["results"] = results;
  return formatJson(j);
}

bool isCohortResultsFile(const std::string& path) {
  // The format key comes first in every file this writes: its head decides, without reading
  // (or parsing) a large uncertainty shard twice.
  std::ifstream in(path, std::ios::binary);
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return head.find(std::string("\"format\": \"") + kFormat + "\"") != std::string::npos;
}

CohortResultsFile readCohortResultsFile(const std::string& path) {
  Json doc;
  try {
    doc = Json::parse(readFile(path, kMaxResultsFileBytes));
  } catch (const Json::parse_error& e) {
    throw InputError(path + ": expected the JSON of a cohort results file (sweep COHORT.yaml --shard K/N), found text "
                     "that is not JSON (" + e.what() + ")");
  }
  const Fields f(path, doc);
  if (f.text("format") != kFormat) fail(path, "format", std::string("\"") + kFormat + "\"", describe(doc.at("format")));
  if (f.whole("format_version", 1000) != kFormatVersion)
    fail(path, "format_version", std::to_string(kFormatVersion), describe(doc.at("format_version")));
  CohortResultsFile file;
  file.path = path;
  file.run.study = f.text("study");
  file.run.studyPath = f.text("study_path");
  file.run.version = f.text("swingsim_version");
  file.run.inputsFingerprint = f.text("inputs_fingerprint");
  file.run.participants = static_cast<int>(f.whole("participants", static_cast<std::uint64_t>(kMaxCohortParticipants)));
  file.run.seed = f.whole("seed", std::numeric_limits<std::uint64_t>::max());
  const Json& shard = f.at("shard");
  if (!shard.is_null()) {
    const Fields s(path, shard, "shard.");
    file.sharded = true;
    file.shardCount = static_cast<int>(s.whole("count", 1000000));
    if (file.shardCount < 1) fail(path, "shard.count", "a shard count of at least 1", "0");
    file.shardIndex = static_cast<int>(s.whole("index", static_cast<std::uint64_t>(file.shardCount - 1)));
  }
  const auto total = static_cast<std::uint64_t>(file.run.participants);
  file.first = f.whole("first_participant", total);
  file.last = f.whole("last_participant", total);
  if (file.last < file.first)
    fail(path, "last_participant", "at least first_participant (" + std::to_string(file.first) + ")",
         std::to_string(file.last));
  const Json& results = f.at("results");
  if (!results.is_array() || results.size() != file.last - file.first)
    fail(path, "results", "a list of " + std::to_string(file.last - file.first) + " participants",
         results.is_array() ? "a list of " + std::to_string(results.size()) : describe(results));
  for (std::size_t k = 0; k < results.size(); ++k)
    file.results.push_back(readResult(path, results[k], "results[" + std::to_string(k) + "]."));
  if (f.whole("participants_finished", total) != file.countFinished())
    fail(path, "participants_finished", std::to_string(file.countFinished()) + " (the results with \"ran\": true)",
         describe(doc.at("participants_finished")));
  if (f.flag("partial") != file.isPartial())
    fail(path, "partial", file.isPartial() ? "true (some results have not run)" : "false (every result ran)",
         file.isPartial() ? "false" : "true");
  return file;
}

void checkSameCohortRun(const CohortRunIdentity& expected, const CohortResultsFile& found, const std::string& what) {
  auto differ = [&](const std::string& key, const std::string& e, const std::string& g) {
    throw InputError(found.path + ": " + key + ": expected " + e + " (" + what + "), found " + g +
                     ": these results belong to another cohort run");
  };
  const CohortRunIdentity& got = found.run;
  if (got.study != expected.study) differ("study", "\"" + expected.study + "\"", "\"" + got.study + "\"");
  if (got.participants != expected.participants)
    differ("participants", std::to_string(expected.participants), std::to_string(got.participants));
  if (got.seed != expected.seed) differ("seed", std::to_string(expected.seed), std::to_string(got.seed));
  if (got.inputsFingerprint != expected.inputsFingerprint)
    differ("inputs_fingerprint", expected.inputsFingerprint + " (" + expected.studyPath + ")",
           got.inputsFingerprint + " (" + got.studyPath + "): the study, its template or a knee model differs");
  if (got.version != expected.version) differ("swingsim_version", expected.version, got.version);
}

std::vector<CohortParticipantResult> mergeCohortShards(const std::vector<CohortResultsFile>& shards) {
  if (shards.empty()) throw InputError("merge: expected at least one shard file, found none");
  const CohortResultsFile& head = shards.front();
  std::map<int, const CohortResultsFile*> byIndex;
  for (const auto& s : shards) {
    if (!s.sharded)
      throw InputError(s.path + ": shard: expected {\"index\": K, \"count\": N} (a file written by sweep --shard K/N), "
                       "found null (the partial result of a whole run: rerun its sweep command to resume it)");
    if (s.isPartial())
      throw InputError(s.path + ": partial: expected false (a finished shard), found true (" +
                       std::to_string(s.countFinished()) + " of " + std::to_string(s.last - s.first) +
                       " participants ran): rerun that shard's sweep --shard command to finish it");
    if (&s != &head) checkSameCohortRun(head.run, s, "the first shard, " + head.path);
    if (s.shardCount != head.shardCount)
      fail(s.path, "shard.count", std::to_string(head.shardCount) + " (the first shard, " + head.path + ")",
           std::to_string(s.shardCount));
    const auto slice = calcShardSwings(static_cast<std::size_t>(s.run.participants), s.shardIndex, s.shardCount);
    if (s.first != slice.first || s.last != slice.second)
      fail(s.path, "first_participant, last_participant",
           std::to_string(slice.first) + ", " + std::to_string(slice.second) + " (shard " + std::to_string(s.shardIndex) +
               "/" + std::to_string(s.shardCount) + ")",
           std::to_string(s.first) + ", " + std::to_string(s.last));
    const auto [it, added] = byIndex.emplace(s.shardIndex, &s);
    if (!added)
      fail(s.path, "shard.index", "each shard once", "shard " + std::to_string(s.shardIndex) + " again (also in " +
                                                         it->second->path + ")");
  }
  std::string missing;
  for (int k = 0; k < head.shardCount; ++k)
    if (!byIndex.count(k)) missing += (missing.empty() ? "" : ", ") + std::to_string(k);
  if (!missing.empty())
    throw InputError("merge: expected all " + std::to_string(head.shardCount) + " shards of " + head.run.study +
                     ", found " + std::to_string(byIndex.size()) + "; missing K = " + missing + " (files " +
                     cohortShardFileName(0, head.shardCount) + " and the like)");
  std::vector<CohortParticipantResult> all(static_cast<std::size_t>(head.run.participants));
  for (const auto& s : shards)
    for (std::size_t k = 0; k < s.results.size(); ++k) all[s.first + k] = s.results[k];
  return all;
}

std::string cohortPartialFileName() { return "cohort.partial.json"; }

std::string cohortShardFileName(int index, int shards) {
  const int width = static_cast<int>(std::to_string(std::max(0, shards - 1)).size());
  char buf[96];
  std::snprintf(buf, sizeof buf, "cohort-shard-%0*d-of-%d.json", width, index, shards);
  return buf;
}

}  // namespace swingsim
